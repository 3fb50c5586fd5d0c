// graph_interp.glsl: the scene graph interpreter (docs/scene-graph.md,
// "Two ways to evaluate"). Included after graph_buffers.glsl and the
// generated dispatch (shader/graph_interp.cpp: msGraphPrim, msGraphOp, and
// for modifiers msGraphBegin, msGraphEnd, msGraphFloor, each a switch on
// the functions the graph uses) and the defines MS_GRAPH_STACK,
// MS_GRAPH_FRAMES, MS_GRAPH_LEN, MS_GRAPH_L, MS_INDEX, MS_GRAPH_COPIES and,
// with a pruning grid, MS_GRID_*. Gives msGraphRun() and, outside the
// pruning pass, map().
#pragma once

// A leaf's or modifier's point: its folded transform's rows and offset at o.
vec3 msGraphLocal(uint o, vec3 p) {
  return vec3(dot(vec3(msGraphF[o], msGraphF[o + 1u], msGraphF[o + 2u]), p),
              dot(vec3(msGraphF[o + 3u], msGraphF[o + 4u], msGraphF[o + 5u]), p),
              dot(vec3(msGraphF[o + 6u], msGraphF[o + 7u], msGraphF[o + 8u]), p)) +
         vec3(msGraphF[o + 9u], msGraphF[o + 10u], msGraphF[o + 11u]);
}
// Leaf i at p: its primitive at the local point, times its scale, with its material.
vec2 msGraphLeaf(uint i, vec3 p) {
  uvec4 n = msGraphNode[i];
  uint o = n.y;
  return vec2(msGraphPrim(n.x, o + 13u, msGraphLocal(o, p)) * msGraphF[o + 12u], float(n.z));
}
vec2 msGraphNodeOp(uint i, vec2 a, vec2 b) {
  uvec4 n = msGraphNode[i];
  return msGraphOp(n.x, n.y, a, b);
}

#if MS_GRAPH_FRAMES > 0
// A modifier's frame: the point before it, the nearest copy's value so
// far, the copy looked at and how many, and where its child starts.
struct MsFrame { vec3 p; vec2 acc; float t, n; uint start; };
// Begins modifier i at instruction k: its child's point.
vec3 msGraphEnter(uint i, uint k, vec3 p, out MsFrame f) {
  uvec4 n = msGraphNode[i];
  f = MsFrame(p, vec2(1e30, 0.0), 0.0, 1.0, k + 1u);
  float count;
  vec3 q = msGraphBegin(n.x, n.y + 13u, msGraphLocal(n.y, p), 0.0, count);
  f.n = count;
  return q;
}
// Ends modifier i with its child's value v: true with p the next copy's
// point when a repetition has one to look at (v is then dropped), else v
// becomes the modifier's value and p the point before it.
bool msGraphLeave(uint i, inout vec2 v, inout vec3 p, inout MsFrame f) {
  uvec4 n = msGraphNode[i];
  vec3 q = msGraphLocal(n.y, f.p);
  if (f.n > 1.5 || f.t > 0.5) {
    if (v.x < f.acc.x) f.acc = v;
    for (float t = f.t + 1.0; t < f.n; t += 1.0) {
      float count;
      vec3 c = msGraphBegin(n.x, n.y + 13u, q, t, count);
      if (msGraphFloor(n.x, n.y + 13u, c) < f.acc.x) {
        f.t = t;
        p = c;
        return true;
      }
    }
    v = f.acc;
  } else {
    v.x = msGraphEnd(n.x, n.y + 13u, v.x, q);
  }
  v.x *= msGraphF[n.y + 12u];
  p = f.p;
  return false;
}
#endif

// The program from `start`, `count` instructions, at p. The loop body is
// there MS_GRAPH_COPIES times (1, 2, 4 or 8): llvmpipe ends an invocation's
// loops after 65,535 iterations in all, and graph_interp.cpp says how many
// copies an unpruned run needs.
#if !defined(MS_GRAPH_PRUNING) || MS_GRAPH_FRAMES > 0
vec2 msGraphRun(uint start, uint count, vec3 p) {
  vec2 st[MS_GRAPH_STACK];
  int sp = 0;
#if MS_GRAPH_FRAMES > 0
  MsFrame fr[MS_GRAPH_FRAMES];
  int fp = 0;
#endif
  uint end = start + count;
  for (uint k = start; k < end;) {
#include "graph_step.glsl"
#if MS_GRAPH_COPIES >= 2
#include "graph_step.glsl"
#endif
#if MS_GRAPH_COPIES >= 4
#include "graph_step.glsl"
#include "graph_step.glsl"
#endif
#if MS_GRAPH_COPIES >= 8
#include "graph_step.glsl"
#include "graph_step.glsl"
#include "graph_step.glsl"
#include "graph_step.glsl"
#endif
  }
  return st[0];
}
#endif

#ifndef MS_GRAPH_PRUNING
#ifdef MS_GRID_LEVELS
// Past the last level the field is taken to be at least the distance to
// the graph's box (the head's last two entries), as the shadows' reach
// already takes it (bounds.glsl shadowBoundsPad).
float msGraphBoxDistance(vec3 p) {
  vec3 lo = uintBitsToFloat(msGraphCell[1 + 3 * MS_GRID_LEVELS].xyz);
  vec3 hi = uintBitsToFloat(msGraphCell[2 + 3 * MS_GRID_LEVELS].xyz);
  return length(max(max(lo - p, p - hi), vec3(0.0)));
}
// The list of the finest level's cell holding p; one msGraphRun() at the
// end, as every call site of it is compiled again wherever map() is inlined.
vec2 map(vec3 p) {
  uint start = 0u, count = 0u;
#define MS_LEVEL 0
#include "graph_level.glsl"
#undef MS_LEVEL
#if MS_GRID_LEVELS > 1
#define MS_LEVEL 1
#include "graph_level.glsl"
#undef MS_LEVEL
#endif
#if MS_GRID_LEVELS > 2
#define MS_LEVEL 2
#include "graph_level.glsl"
#undef MS_LEVEL
#endif
  if (count == 0u) return vec2(msGraphBoxDistance(p), 0.0);
  return msGraphRun(start, count, p);
}
#else
vec2 map(vec3 p) {
  return msGraphRun(0u, MS_GRAPH_LEN, p);
}
#endif
#endif
