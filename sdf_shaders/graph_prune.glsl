// graph_prune.glsl: the scene graph's pruning pass (docs/scene-graph.md,
// "Pruning"), a compute shader. Included after graph_buffers.glsl and
// graph_interp.glsl with MS_GRAPH_PRUNING defined, and after the generated
// rules (shader/graph_prune.cpp: msReach, msGraphPrune, a switch on the
// combinators the graph uses).
//
// One invocation a cell walks its input list (the whole
// program for a coarse cell, its coarse cell's list for a fine one) at the
// cell's centre, keeping an interval per stack entry (value -+ L r) and
// the cell's list so far; a dropped child's instructions are cut out. A
// coarse cell writes its list in its own slot; a fine one builds it in
// private memory and copies it to the pool, taking its share atomically,
// so the lists take what they need rather than the longest one's room.
#pragma once

int msDrop(uint fn, uint o, vec2 ia, vec2 ib) {
  float rb = msReach(fn, o, ia), ra = msReach(fn, o, ib);
  if (rb >= 0.0 && ib.x >= ia.y + rb) return 1;
  if (ra >= 0.0 && ia.x >= ib.y + ra) return 2;
  return 0;
}
// Engrave, groove, tongue: b goes where its least |b| on the cell reaches.
int msCut(uint fn, uint o, vec2 ia, vec2 ib) {
  return max(max(ib.x, -ib.y), 0.0) >= msReach(fn, o, ia) ? 1 : 0;
}
struct MsEntry { vec2 v; float lo, hi; uint start, count; };
layout(local_size_x = 64) in;
// uLevel 0 prunes coarse cells, 1 fine ones; uGrid is the grid level.
uniform int uLevel;
uniform int uGrid;
uint gList[MS_GRID_LIST];
uint gBase;
void msPut(uint at, uint v) {
  if (uLevel == 0) msGraphProg[gBase + at] = v; else gList[at] = v;
}
uint msGet(uint at) { return uLevel == 0 ? msGraphProg[gBase + at] : gList[at]; }
void msSetCell(uint index, uvec4 cell, uvec4 h0) {
  if (uLevel == 0) msGraphCoarse[h0.y + index] = cell; else msGraphCell[MS_GRID_HEADER + h0.x + index] = cell;
}
void main() {
  uint e = uint(1 + 3 * uGrid);
  uvec4 ga = msGraphCell[e], gb = msGraphCell[e + 1u], gd = msGraphCell[e + 2u];
  uvec4 h0 = uvec4(ga.w, gb.w, 0u, 0u);  // where this level's fine and coarse cells start
  ivec3 fine = ivec3(gd.xyz), coarseDims = (fine + MS_GRID_SPLIT - 1) / MS_GRID_SPLIT;
  ivec3 dims = uLevel == 0 ? coarseDims : fine;
  uint cellIndex = gl_GlobalInvocationID.x;
  if (cellIndex >= uint(dims.x * dims.y * dims.z)) return;
  ivec3 c = ivec3(int(cellIndex) % dims.x, (int(cellIndex) / dims.x) % dims.y, int(cellIndex) / (dims.x * dims.y));
  vec3 size = uintBitsToFloat(gb.xyz) * (uLevel == 0 ? float(MS_GRID_SPLIT) : 1.0);
  vec3 lo = uintBitsToFloat(ga.xyz) + vec3(c) * size;
  vec3 centre = lo + 0.5 * size;
  if (uGrid > 0) {
    // Inside the finer level (by a margin for rounding) no point looks here.
    uvec4 ia = msGraphCell[e - 3u], ib = msGraphCell[e - 2u], id = msGraphCell[e - 1u];
    vec3 icell = uintBitsToFloat(ib.xyz), imin = uintBitsToFloat(ia.xyz) + 1e-3 * icell;
    vec3 imax = uintBitsToFloat(ia.xyz) + icell * (vec3(id.xyz) - 1e-3);
    if (all(greaterThanEqual(lo, imin)) && all(lessThanEqual(lo + size, imax))) {
      msSetCell(cellIndex, uvec4(0u), h0);
      return;
    }
  }
  // The half diagonal, a little over: a point the tracer files under this
  // cell may lie a rounding error outside it.
  float r = 0.5 * length(size) * 1.001 + 1e-6;
  uint inStart = 0u, inCount = MS_GRAPH_LEN, listMax = MS_COARSE_LIST;
  gBase = MS_GRAPH_LEN + (h0.y + cellIndex) * MS_COARSE_LIST;
  if (uLevel == 1) {
    ivec3 pc = c / MS_GRID_SPLIT;
    uvec4 parent = msGraphCoarse[h0.y + uint(pc.x + coarseDims.x * (pc.y + coarseDims.y * pc.z))];
    if (parent.w == 2u) {  // far: the fine cell keeps its coarse cell's bound
      msSetCell(cellIndex, parent, h0);
      return;
    }
    inStart = parent.x;
    inCount = parent.y;
    listMax = MS_GRID_LIST;
  }
  MsEntry st[MS_GRAPH_STACK];
  int sp = 0;
  uint len = 0u;
  bool overflow = false;
  for (uint k = inStart; k < inStart + inCount; ++k) {
    uint ins = msGraphProg[k];
    uint i = ins & MS_INDEX;
    float L = uintBitsToFloat(msGraphNode[i].w);
    if ((ins & 0x80000000u) != 0u) {
      vec2 v = msGraphLeaf(i, centre);
      st[sp++] = MsEntry(v, v.x - L * r, v.x + L * r, len, 1u);
      if (len < listMax) msPut(len, ins); else overflow = true;
      ++len;
      continue;
    }
#if MS_GRAPH_FRAMES > 0
    if ((ins & 0x20000000u) != 0u) {
      // A modifier is kept or dropped whole: its value at the centre,
      // widened by its bound, stands for its unit of instructions.
      uint unit = msGraphNode[i].z;
      vec2 v = msGraphRun(k, unit, centre);
      st[sp++] = MsEntry(v, v.x - L * r, v.x + L * r, len, unit);
      for (uint j = 0u; j < unit; ++j) {
        if (len < listMax) msPut(len, msGraphProg[k + j]); else overflow = true;
        ++len;
      }
      k += unit - 1u;
      continue;
    }
#endif
    MsEntry y = st[--sp];
    MsEntry x = st[--sp];  // x ran first
    bool swap = (ins & 0x40000000u) != 0u;
    MsEntry a = swap ? y : x, b = swap ? x : y;
    vec2 v = msGraphNodeOp(i, a.v, b.v);
    uvec4 n = msGraphNode[i];
    int drop = msGraphPrune(n.x, n.y, vec2(a.lo, a.hi), vec2(b.lo, b.hi));
    MsEntry res = MsEntry(v, v.x - L * r, v.x + L * r, x.start, 0u);
    if (drop == 0) {
      if (len < listMax) msPut(len, ins); else overflow = true;
      ++len;
      res.count = x.count + y.count + 1u;
    } else {
      MsEntry keep = drop == 1 ? a : b;
      // Keep y's instructions in x's place when x goes.
      if (keep.start != x.start && !overflow)
        for (uint j = 0u; j < keep.count; ++j) msPut(x.start + j, msGet(keep.start + j));
      res.count = keep.count;
      len = x.start + keep.count;
    }
    st[sp++] = res;
  }
  uvec4 cell = uvec4(inStart, inCount, 0u, 1u);  // the input list, unpruned here
  if (!overflow && uLevel == 0) cell = uvec4(gBase, len, 0u, 0u);
  // An outer coarse cell too crowded for a list is far: it keeps the
  // root's value at its centre, a lower bound by the Lipschitz bound.
  // So is an outer fine cell, with the root's value at its own centre.
  if (overflow && uGrid > 0) cell = uvec4(floatBitsToUint(st[0].v.x), 0u, 0u, uLevel == 0 ? 2u : 3u);
  if (!overflow && uLevel == 1) {
    uvec4 pool = msGraphCell[0];  // where the pool starts, its size
    uint at = atomicAdd(msPoolUsed, len);
    if (at + len <= pool.y) {
      for (uint j = 0u; j < len; ++j) msGraphProg[pool.x + at + j] = gList[j];
      cell = uvec4(pool.x + at, len, 0u, 0u);
    }
  }
  msSetCell(cellIndex, cell, h0);
}
