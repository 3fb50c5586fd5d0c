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
#if MS_GRAPH_FRAMES > 0
// A modifier the walk goes inside (msGraphRegion): the cell's ball before
// it, the modifier's value at the cell's centre, and where its begin
// instruction went in the list.
struct MsRegion { vec3 centre; float r; vec2 v; uint start; };
// Instructions from the begin at k to its end, in a list whose modifiers
// may have been pruned inside (so shorter than the node's unit).
uint msUnitIn(uint k, uint end) {
  int depth = 0;
  for (uint j = k; j < end; ++j) {
    uint ins = msGraphProg[j];
    if ((ins & 0x80000000u) != 0u) continue;
    if ((ins & 0x20000000u) != 0u) ++depth;
    else if ((ins & 0x10000000u) != 0u && --depth == 0) return j - k + 1u;
  }
  return end - k;
}
// A repetition's copies for the points within r of c (in its frame; its
// begin instruction at k, unit instructions to its end): a ball holding
// the ball's copy in each copy domRepeatNode may look at for its points,
// as its centre and radius r2 (the ball's about the copies' centres). Where every point of the ball
// looks first at the same copy j0, a copy whose box lies farther than
// j0's value can reach over the ball is skipped there (opCopyFloor), and
// is left out; past 64 copies in range, none is.
vec3 msRepeatRegion(vec3 c, float r, uint k, uint unit, vec3 spacing, vec3 count, vec3 lo, vec3 hi, float slack,
                    out float r2) {
  vec3 rep = step(1e-30, spacing);
  vec3 sp = mix(vec3(1.0), spacing, rep);
  vec3 lim = mix(vec3(1e9), count, step(0.0, count));
  vec3 jlo = clamp(rep * floor((c - r - hi - slack) / sp), -lim, lim);
  vec3 jhi = clamp(rep * ceil((c + r - lo + slack) / sp), -lim, lim);
  vec3 n = jhi - jlo + 1.0;
  r2 = 0.5 * length(spacing * (jhi - jlo)) * 1.001 + r + 1e-6;
  vec3 whole = c - spacing * 0.5 * (jlo + jhi);
  if (n.x * n.y * n.z > 64.0) return whole;
  vec3 j0 = rep * round(c / sp);
  vec3 innerLo = clamp(rep * floor((c + r - hi - slack) / sp), -lim, lim);
  vec3 innerHi = clamp(rep * ceil((c - r - lo + slack) / sp), -lim, lim);
  if (any(notEqual(rep * round((c - r) / sp), rep * round((c + r) / sp))) || any(greaterThan(innerLo, j0)) ||
      any(lessThan(innerHi, j0)))
    return whole;
  uint root = msGraphProg[k + unit - 2u] & MS_INDEX;
  float reach = msGraphRun(k + 1u, unit - 2u, c - spacing * j0).x + uintBitsToFloat(msGraphNode[root].w) * r;
  vec3 bmin = vec3(1e30), bmax = vec3(-1e30);
  for (float z = jlo.z; z <= jhi.z; z += 1.0)
    for (float y = jlo.y; y <= jhi.y; y += 1.0)
      for (float x = jlo.x; x <= jhi.x; x += 1.0) {
        vec3 j = vec3(x, y, z), q = c - spacing * j;
        if (j != j0 && length(max(max(lo - q, q - hi), vec3(0.0))) - r - slack >= reach) continue;
        bmin = min(bmin, q);
        bmax = max(bmax, q);
      }
  r2 = 0.5 * length(bmax - bmin) * 1.001 + r + 1e-6;
  return 0.5 * (bmin + bmax);
}
#endif
layout(local_size_x = 64) in;
// uLevel 0 prunes coarse cells, 1 fine ones; uGrid is the grid level.
uniform int uLevel;
uniform int uGrid;
// 1: only the cells of this level msDirty lists (its count first), as a
// new pose of the graph needs (shader/graph_repose.h).
uniform int uSubset;
layout(std430, binding = 8) readonly buffer MsDirty { uint msDirty[]; };
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
  if (uSubset != 0) {
    if (cellIndex >= msDirty[0]) return;
    cellIndex = msDirty[1u + cellIndex];
  }
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
#if MS_GRAPH_FRAMES > 0
  MsRegion rg[MS_GRAPH_FRAMES];
  int rp = 0;
#endif
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
      uvec4 n = msGraphNode[i];
      vec3 c2;
      float r2;
      uint unitIn = uLevel == 0 ? n.z : msUnitIn(k, inStart + inCount);
      if (msGraphRegion(n.x, n.y + 13u, msGraphLocal(n.y, centre), r / msGraphF[n.y + 12u], k, unitIn, c2, r2)) {
        // Inside it the walk goes on, pruning its child for the ball its
        // points map into; its end restores the cell's ball.
        rg[rp++] = MsRegion(centre, r, msGraphRun(k, unitIn, centre), len);
        centre = c2;
        r = r2;
        if (len < listMax) msPut(len, ins); else overflow = true;
        ++len;
        continue;
      }
      // Else it is kept or dropped whole: its value at the centre, widened
      // by its bound, stands for its unit of instructions (copied whole,
      // so its unit is the node's in any list).
      uint unit = n.z;
      vec2 v = msGraphRun(k, unit, centre);
      st[sp++] = MsEntry(v, v.x - L * r, v.x + L * r, len, unit);
      for (uint j = 0u; j < unit; ++j) {
        if (len < listMax) msPut(len, msGraphProg[k + j]); else overflow = true;
        ++len;
      }
      k += unit - 1u;
      continue;
    }
    if ((ins & 0x10000000u) != 0u) {  // the end of a modifier the walk went inside
      MsRegion g = rg[--rp];
      --sp;  // its child's entry: the modifier's value stands for it
      centre = g.centre;
      r = g.r;
      if (len < listMax) msPut(len, ins); else overflow = true;
      ++len;
      st[sp++] = MsEntry(g.v, g.v.x - L * r, g.v.x + L * r, g.start, len - g.start);
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
    // A cell pruned again for a new pose writes over its old list where the
    // new one fits there (nothing else reads it), so poses leak no room.
    uvec4 old = msGraphCell[MS_GRID_HEADER + h0.x + cellIndex];
    bool inPlace = uSubset != 0 && old.w == 0u && old.x >= pool.x && len <= old.y;
    uint at = inPlace ? old.x - pool.x : atomicAdd(msPoolUsed, len);
    if (inPlace || at + len <= pool.y) {
      for (uint j = 0u; j < len; ++j) msGraphProg[pool.x + at + j] = gList[j];
      cell = uvec4(pool.x + at, len, 0u, 0u);
    }
  }
  // The field's upper bound on the cell, which a new pose reads to tell
  // the cells a moved node cannot reach (shader/graph_repose.h).
  cell.z = floatBitsToUint(st[0].hi);
  msSetCell(cellIndex, cell, h0);
}
