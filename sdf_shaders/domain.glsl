// domain.glsl: domain operators (dom*), maps of the point handed to a
// distance function: repetition, mirrors and folds, rotations, twist, bend,
// elongation and revolution. A claim here is the claim of sdX(domY(p, ...))
// for an exact sdX that meets the stated condition, in the notation of
// primitives.glsl. Rotations are isometries. A fold into the chamber of a
// reflection group (mirror repetition, mirrors, the octahedral and
// tetrahedral folds, the polar fold of a mirror-symmetric shape) keeps
// exactness for a shape inside the chamber: from a point of the chamber the
// shape's nearest copy is the one in the chamber. Included by operators.glsl.
#pragma once
#include "common.glsl"

#if defined(USE_DOMFOLDTETRAHEDRAL) && !defined(USE_DOMFOLDOCTAHEDRAL)
#define USE_DOMFOLDOCTAHEDRAL 1
#endif

// ---- repetition ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREPEAT)
// Infinite repetition with cell size `period` (> 0 per component): p
// relative to its cell's centre. Exact when the shape fits its cell and is
// mirror-symmetric about the cell's centre planes; otherwise a neighbour can
// be nearer and the field may overestimate. Repeat only some axes through
// swizzles: p.xz = domRepeat(p.xz, vec2(4.0)). [exact; L = 1]
float domRepeat(float p, float period) { return p - period * round(p / period); }
vec2  domRepeat(vec2 p, vec2 period)   { return p - period * round(p / period); }
vec3  domRepeat(vec3 p, vec3 period)   { return p - period * round(p / period); }
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREPEATLIMITED)
// Limited repetition: cells -limit..+limit (whole numbers >= 0) per axis,
// centred on the origin; beyond them the outermost copy is used. Exact under
// domRepeat's condition. [exact; L = 1]
float domRepeatLimited(float p, float period, float limit) {
  return p - period * clamp(round(p / period), -limit, limit);
}
vec2  domRepeatLimited(vec2 p, vec2 period, vec2 limit) {
  return p - period * clamp(round(p / period), -limit, limit);
}
vec3  domRepeatLimited(vec3 p, vec3 period, vec3 limit) {
  return p - period * clamp(round(p / period), -limit, limit);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREPEATCELL)
// The cell index domRepeatLimited puts p in, for variation between copies:
// p - period * index is domRepeatLimited(p, period, limit). [index]
vec2  domRepeatCell(vec2 p, vec2 period, vec2 limit) {
  return clamp(round(p / period), -limit, limit);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREPEATMIRROR)
// Repetition that mirrors every other cell, so neighbours meet face to face:
// the reflection group of the cell walls. Exact for any shape that fits its
// cell, symmetric or not. [exact; L = 1]
float domRepeatMirror(float p, float period) {
  float c = round(p / period);
  float q = p - period * c;
  return mod(c, 2.0) == 0.0 ? q : -q;
}
vec2  domRepeatMirror(vec2 p, vec2 period) {
  return vec2(domRepeatMirror(p.x, period.x), domRepeatMirror(p.y, period.y));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREPEATPOLAR)
// n copies around the origin of the plane: p turned into the sector of
// angle 2 pi / n centred on +x. Exact for a shape inside that sector and
// mirror-symmetric about the x axis (otherwise it may overestimate near the
// sector's sides). [exact; L = 1]
vec2 domRepeatPolar(vec2 p, float n) {
  float sector = TAU / n;
  float a = mod(atan(p.y, p.x) + 0.5 * sector, sector) - 0.5 * sector;
  return length(p) * vec2(cos(a), sin(a));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMPOLARCELL)
// Which of the n sectors of domRepeatPolar p lies in, 0..n-1
// counter-clockwise from +x. [index]
float domPolarCell(vec2 p, float n) {
  float sector = TAU / n;
  return mod(floor((atan(p.y, p.x) + 0.5 * sector) / sector), n);
}
#endif

// ---- mirrors and folds ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMMIRROR)
// Mirrors across the plane p = 0 and moves the copy to +offset: a shape in
// q >= -offset of the result appears twice. [exact; L = 1]
float domMirror(float p, float offset) {
  return abs(p) - offset;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMMIRROROCTANT)
// Mirrors across x = 0, y = 0 and the diagonal x = y (8 copies), then moves
// by -offset along both axes: exact for a shape in the chamber
// 0 <= y <= x before the move. [exact; L = 1]
vec2 domMirrorOctant(vec2 p, float offset) {
  p = abs(p);
  if (p.y > p.x) p = p.yx;
  return p - offset;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREFLECT)
// Reflects p across the plane dot(p, n) + w = 0 (unit n) when it is on the
// plane's negative side: a shape on the positive side appears twice (the
// graph's `mirror`). A fold: exact for a shape on the positive side.
// [exact; L = 1]
vec3 domReflect(vec3 p, vec3 n, float w) {
  float t = dot(p, n) + w;
  return t < 0.0 ? p - 2.0 * t * n : p;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMFOLDOCTAHEDRAL)
// The cube's 48-fold symmetry: |p| sorted so x >= y >= z >= 0. Exact for a
// shape in that chamber (a cube or octahedron built from one wedge).
// [exact; L = 1]
vec3 domFoldOctahedral(vec3 p) {
  p = abs(p);
  if (p.x < p.y) p.xy = p.yx;
  if (p.y < p.z) p.yz = p.zy;
  if (p.x < p.y) p.xy = p.yx;
  return p;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMFOLDTETRAHEDRAL)
// The regular tetrahedron's 24-fold symmetry (vertices (1, 1, 1),
// (1, -1, -1), (-1, 1, -1), (-1, -1, 1)): permutations with an even number
// of sign changes, folding p into x >= y >= |z|. Exact for a shape in that
// chamber. [exact; L = 1]
vec3 domFoldTetrahedral(vec3 p) {
  bool odd = p.x * p.y * p.z < 0.0;
  p = domFoldOctahedral(p);
  if (odd) p.z = -p.z;
  return p;
}
#endif

// ---- rotations (isometries: every claim is kept) ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMROTATE)
// Rotates a shape counter-clockwise by angle a (radians) in the plane of
// the two coordinates passed: sdX(vec3(domRotate(p.xz, a), p.y).xzy).
// [exact; L = 1]
vec2 domRotate(vec2 p, float a) {
  float c = cos(a), s = sin(a);
  return vec2(c * p.x + s * p.y, c * p.y - s * p.x);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMROTATE45)
// domRotate(p, pi / 4) with no trigonometry. [exact; L = 1]
vec2 domRotate45(vec2 p) {
  return vec2(p.x + p.y, p.y - p.x) * 0.70710678;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMROTATEAXIS)
// Rotates a shape by angle a (radians, right-handed) about the unit axis
// through the origin (Rodrigues' formula applied to p with -a).
// [exact; L = 1]
vec3 domRotateAxis(vec3 p, vec3 axis, float a) {
  float c = cos(a), s = sin(a);
  return p * c - cross(axis, p) * s + axis * dot(axis, p) * (1.0 - c);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMROTATEQUAT)
// Rotates a shape by the unit quaternion q = (axis * sin(a/2), cos(a/2)),
// the same rotation as domRotateAxis(p, axis, a): p turned by the inverse,
// p + 2 w (v x p) + 2 v x (v x p) with v = -q.xyz. [exact; L = 1]
vec3 domRotateQuat(vec3 p, vec4 q) {
  vec3 v = -q.xyz;
  vec3 t = 2.0 * cross(v, p);
  return p + q.w * t + cross(v, t);
}
#endif

// ---- deformations ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMTWIST)
// Twists space about the y axis by k radians per unit of y. Within the
// cylinder |p.xz| <= r (keep [bounds] inside it) the map's Jacobian has
// largest singular value (a + sqrt(a a + 4)) / 2 with a = |k| r: set
// [quality] lipschitz to at least that. [bound; L = (a + sqrt(a*a + 4)) / 2 with a = abs(k) r]
vec3 domTwist(vec3 p, float k) {
  float c = cos(k * p.y), s = sin(k * p.y);
  return vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMBEND)
// Bends space in the xy plane: p.xy turned by k x radians, so a bar along
// x curls up into an arc. Within |p.xy| <= r the Jacobian's largest
// singular value is 1 + |k| r (at (0, -r) for k > 0): set [quality]
// lipschitz to at least that. [bound; L = 1 + abs(k) r]
vec3 domBend(vec3 p, float k) {
  float c = cos(k * p.x), s = sin(k * p.x);
  return vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMELONGATE)
// Stretches a shape by inserting a slab of size 2h at its centre along
// each axis: p - clamp(p, -h, h). Exact outside; inside the inserted part
// it reads the shape's centre value, a bound. [exact outside; L = 1]
vec3 domElongate(vec3 p, vec3 h) {
  return p - clamp(p, -h, h);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREVOLVE)
// The 2D point of a solid of revolution about the y axis:
// (|p.xz| - o, p.y) for a 2D shape swept round a circle of radius o. Exact
// for an exact 2D shape that lies in x >= -o (it does not cross the axis).
// [exact; L = 1]
vec2 domRevolve(vec3 p, float o) {
  return vec2(length(p.xz) - o, p.y);
}
#endif
