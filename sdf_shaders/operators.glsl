// operators.glsl: combining and folding distance fields. Distance-only
// (float) and material-carrying (vec2: x = distance, y = material id)
// versions. Bounds assume 1-Lipschitz inputs. A union of exact fields is
// exact outside and a bound inside; intersection and subtraction are bounds
// (never overestimate), so sphere tracing stays safe with LIPSCHITZ 1.
// Each function is guarded by USE_<NAME>: a specialized shader defines
// MS_LIBRARY_SUBSET and USE_<NAME> for the names its map calls, so only those
// are compiled; without MS_LIBRARY_SUBSET (generic, Shadertoy) all are.
#pragma once
#include "common.glsl"

// The smooth subtraction and intersection are built on the smooth union.
#if defined(USE_OPSMOOTHSUBTRACTION) || defined(USE_OPSMOOTHINTERSECTION)
#ifndef USE_OPSMOOTHUNION
#define USE_OPSMOOTHUNION 1
#endif
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPUNION)
// Union: min. 1-Lipschitz; exact outside all shapes.
float opUnion(float a, float b) { return min(a, b); }
// Union carrying the nearer shape's material. 1-Lipschitz.
vec2  opUnion(vec2 a, vec2 b)   { return a.x < b.x ? a : b; }
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPINTERSECTION)
// Intersection: max. 1-Lipschitz bound (may underestimate near edges).
float opIntersection(float a, float b) { return max(a, b); }
// Intersection carrying the material of the surface that bounds the result. 1-Lipschitz bound.
vec2  opIntersection(vec2 a, vec2 b)   { return a.x > b.x ? a : b; }
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSUBTRACTION)
// Subtraction "a minus b": max(a, -b). 1-Lipschitz bound.
float opSubtraction(float a, float b) { return max(a, -b); }
// a minus b; the cut face takes b's material (pass vec2(b.x, a.y) to keep a's). 1-Lipschitz bound.
vec2  opSubtraction(vec2 a, vec2 b) {
  return a.x > -b.x ? a : vec2(-b.x, b.y);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSMOOTHUNION)
// Smooth union, quadratic polynomial smin with blend radius k > 0 (Quilez).
// Still 1-Lipschitz (the weights of the two gradients sum to 1), but only a
// bound on the distance to the blended surface, never exact in the blend zone.
float opSmoothUnion(float a, float b, float k) {
  float h = max(k - abs(a - b), 0.0) / max(k, 1e-6);
  return min(a, b) - h * h * k * 0.25;
}
// Smooth union carrying the nearer shape's material. 1-Lipschitz bound.
vec2  opSmoothUnion(vec2 a, vec2 b, float k) {
  return vec2(opSmoothUnion(a.x, b.x, k), a.x < b.x ? a.y : b.y);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSMOOTHSUBTRACTION)
// Smooth subtraction "a minus b" with blend radius k (smooth max of a, -b). 1-Lipschitz bound.
float opSmoothSubtraction(float a, float b, float k) {
  return -opSmoothUnion(-a, b, k);
}
// Smooth subtraction carrying a's material outside the cut, b's on it. 1-Lipschitz bound.
vec2  opSmoothSubtraction(vec2 a, vec2 b, float k) {
  return vec2(opSmoothSubtraction(a.x, b.x, k), a.x > -b.x ? a.y : b.y);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSMOOTHINTERSECTION)
// Smooth intersection with blend radius k (smooth max). 1-Lipschitz bound.
float opSmoothIntersection(float a, float b, float k) {
  return -opSmoothUnion(-a, -b, k);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPREPEAT)
// Infinite domain repetition with cell size `period` (> 0 per component):
// returns p relative to its cell centre. The result is exact when the shape is
// mirror-symmetric about its cell's centre planes and fits inside the cell;
// otherwise a neighbour can be nearer and the field may overestimate (use a
// larger period, or raise LIPSCHITZ). Repeat only some axes via swizzles:
// p.xz = opRepeat(p.xz, vec2(4.0)).
float opRepeat(float p, float period) { return p - period * round(p / period); }
vec2  opRepeat(vec2 p, vec2 period)   { return p - period * round(p / period); }
vec3  opRepeat(vec3 p, vec3 period)   { return p - period * round(p / period); }
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPREPEATLIMITED)
// Limited repetition: cells -limit..+limit (whole numbers >= 0) per axis,
// centred on the origin; beyond them the outermost copy is used. Same
// guarantee as opRepeat (exact for symmetric shapes that fit their cell).
float opRepeatLimited(float p, float period, float limit) {
  return p - period * clamp(round(p / period), -limit, limit);
}
vec2  opRepeatLimited(vec2 p, vec2 period, vec2 limit) {
  return p - period * clamp(round(p / period), -limit, limit);
}
vec3  opRepeatLimited(vec3 p, vec3 period, vec3 limit) {
  return p - period * clamp(round(p / period), -limit, limit);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPREPEATCELL)
// Index of the cell opRepeatLimited puts p in (for per-copy variation). Not a distance.
vec2  opRepeatCell(vec2 p, vec2 period, vec2 limit) {
  return clamp(round(p / period), -limit, limit);
}
#endif
