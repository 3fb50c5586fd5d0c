// graph_step.glsl: one step of the scene graph interpreter's loop
// (graph_interp.glsl's msGraphRun, which includes it MS_GRAPH_COPIES times
// over: no #pragma once). A leaf, and the combinator after it when there
// is one (a union chain's program alternates them), or a modifier's begin
// or end.
    if (k < end) {
      uint ins = msGraphProg[k];
      if ((ins & 0x80000000u) != 0u) {
        st[sp++] = msGraphLeaf(ins & MS_INDEX, p);
        MS_COUNT_PRIMS(1);
        ++k;
        ins = k < end ? msGraphProg[k] : 0x80000000u;
      }
      if ((ins & 0xB0000000u) == 0u) {
        vec2 b = st[--sp];
        vec2 a = st[--sp];
        if ((ins & 0x40000000u) != 0u) { vec2 t = a; a = b; b = t; }
        st[sp++] = msGraphNodeOp(ins & MS_INDEX, a, b);
        ++k;
      }
#if MS_GRAPH_FRAMES > 0
      else if ((ins & 0x20000000u) != 0u) {
        p = msGraphEnter(ins & MS_INDEX, k, p, fr[fp]);
        ++fp;
        ++k;
      } else if ((ins & 0x10000000u) != 0u) {
        if (msGraphLeave(ins & MS_INDEX, st[sp - 1], p, fr[fp - 1])) {
          k = fr[fp - 1].start;
          --sp;
        } else {
          --fp;
          ++k;
        }
      }
#endif
    }
