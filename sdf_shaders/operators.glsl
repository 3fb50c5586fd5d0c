// operators.glsl: combining distance fields (op*). Distance-only (float)
// and material-carrying (vec2: x = distance, y = material id) versions; the
// claims below are for the float versions with exact 1-Lipschitz inputs, in
// the notation of primitives.glsl. Through combinators.glsl it has the
// chamfered, rounded, columned and stepped blends, pipes, grooves and the
// distance modifiers; through domain.glsl the domain operators (dom*:
// repetition, mirrors, rotations, folds, twist, bend).
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
// Union: min. [exact outside; L = 1]
float opUnion(float a, float b) { return min(a, b); }
// Union carrying the nearer shape's material. 1-Lipschitz.
vec2  opUnion(vec2 a, vec2 b)   { return a.x < b.x ? a : b; }
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPINTERSECTION)
// Intersection: max; too small near the new edges. [bound; L = 1]
float opIntersection(float a, float b) { return max(a, b); }
// Intersection carrying the material of the surface that bounds the result. 1-Lipschitz bound.
vec2  opIntersection(vec2 a, vec2 b)   { return a.x > b.x ? a : b; }
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSUBTRACTION)
// Subtraction "a minus b": max(a, -b). [bound; L = 1]
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
// [bound; L = 1]
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
// Smooth subtraction "a minus b" with blend radius k (smooth max of a, -b). [bound; L = 1]
float opSmoothSubtraction(float a, float b, float k) {
  return -opSmoothUnion(-a, b, k);
}
// Smooth subtraction carrying a's material outside the cut, b's on it. 1-Lipschitz bound.
vec2  opSmoothSubtraction(vec2 a, vec2 b, float k) {
  return vec2(opSmoothSubtraction(a.x, b.x, k), a.x > -b.x ? a.y : b.y);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSMOOTHINTERSECTION)
// Smooth intersection with blend radius k (smooth max). [bound; L = 1]
float opSmoothIntersection(float a, float b, float k) {
  return -opSmoothUnion(-a, -b, k);
}
#endif

#include "combinators.glsl"
#include "domain.glsl"
#include "modifiers.glsl"
