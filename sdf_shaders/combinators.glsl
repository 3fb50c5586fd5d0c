// combinators.glsl: blends that shape the seam where two fields meet, and
// modifiers of one field. Included by operators.glsl; claims as described
// in primitives.glsl, for exact inputs.
//
// The seam blends (chamfer, round, columns, stairs, pipe, engrave) work in
// the plane of (a, b): where the two surfaces meet at right angles that
// plane is Euclidean and they are 1-Lipschitz. Where the surfaces' normals
// are closer than that, a field of (a, b) such as (a + b) / sqrt 2 can grow
// up to sqrt 2 times as fast as p moves: their bound is L = sqrt 2 (set
// [quality] lipschitz, or keep seams near right angles).
#pragma once
#include "common.glsl"

#if defined(USE_OPSUBTRACTIONCHAMFER) && !defined(USE_OPINTERSECTIONCHAMFER)
#define USE_OPINTERSECTIONCHAMFER 1
#endif
#if defined(USE_OPSUBTRACTIONROUND) && !defined(USE_OPINTERSECTIONROUND)
#define USE_OPINTERSECTIONROUND 1
#endif

// ---- seam blends ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPUNIONCHAMFER)
// Union whose inner corner is cut flat at 45 degrees, r along each surface:
// the line a + b = r of the (a, b) plane. [bound; L = 1.4142]
float opUnionChamfer(float a, float b, float r) {
  return min(min(a, b), (a + b - r) * 0.70710678);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPINTERSECTIONCHAMFER)
// Intersection whose outer edge is cut flat at 45 degrees, r along each
// surface. [bound; L = 1.4142]
float opIntersectionChamfer(float a, float b, float r) {
  return max(max(a, b), (a + b + r) * 0.70710678);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSUBTRACTIONCHAMFER)
// a minus b with the cut's edge chamfered by r. [bound; L = 1.4142]
float opSubtractionChamfer(float a, float b, float r) {
  return opIntersectionChamfer(a, -b, r);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPUNIONROUND)
// Union whose inner corner is filled with a quarter circle of radius r: in
// the (a, b) plane, the distance to the circle of radius r centred at
// (r, r), wherever both a and b are below r. [bound; L = 1.4142]
float opUnionRound(float a, float b, float r) {
  vec2 u = max(vec2(r - a, r - b), 0.0);
  return max(r, min(a, b)) - length(u);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPINTERSECTIONROUND)
// Intersection whose outer edge is rounded with radius r. [bound; L = 1.4142]
float opIntersectionRound(float a, float b, float r) {
  vec2 u = max(vec2(r + a, r + b), 0.0);
  return min(-r, max(a, b)) + length(u);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSUBTRACTIONROUND)
// a minus b with the cut's edge rounded by r. [bound; L = 1.4142]
float opSubtractionRound(float a, float b, float r) {
  return opIntersectionRound(a, -b, r);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPUNIONCOLUMNS)
// Union whose inner corner is a chamfer (r along each surface) with n round
// columns standing on it, side by side: in the (a, b) plane, circles of
// diameter r sqrt 2 / n centred on the chamfer line. [bound; L = 1.4142]
float opUnionColumns(float a, float b, float r, float n) {
  const float h = 0.70710678;
  vec2 q = vec2(a - b, a + b) * h;                 // along, across the chamfer line
  float s = r * 1.41421356 / n;                    // one column's width
  float k = clamp(floor((q.x + r * h) / s), 0.0, n - 1.0);
  float column = length(q - vec2((k + 0.5) * s - r * h, r * h)) - 0.5 * s;
  return min(min(a, b), min(q.y - r * h, column));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPUNIONSTAIRS)
// Union whose inner corner is a staircase of n steps over r along each
// surface: in the (a, b) plane, quarter planes a < x_k, b < y_k with their
// corners (x_k, y_k) spaced along the chamfer line; of these only the three
// nearest along the line, where x_k - y_k is closest to a - b, can be
// nearest (or deepest). [bound; L = 1.4142]
float opUnionStairs(float a, float b, float r, float n) {
  float s = r / n;
  float k = clamp(floor((a - b + r) / (2.0 * s)), 0.0, n - 1.0);
  float d = min(a, b);
  for (float i = max(k - 1.0, 0.0); i <= min(k + 1.0, n - 1.0); i += 1.0) {
    vec2 corner = vec2((i + 0.5) * s, r - (i + 0.5) * s);
    d = min(d, msBoxQ(vec2(a, b) - corner));
  }
  return d;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPPIPE)
// A pipe of radius r along the curve where both surfaces meet. [bound; L = 1.4142]
float opPipe(float a, float b, float r) {
  return length(vec2(a, b)) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPENGRAVE)
// Engraves a V-shaped groove, r deep, into a along the surface of b.
// [bound; L = 1.4142]
float opEngrave(float a, float b, float r) {
  return max(a, (a + r - abs(b)) * 0.70710678);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPGROOVE)
// Cuts a square groove ra deep and 2 rb wide into a along the surface of b.
// [bound; L = 1]
float opGroove(float a, float b, float ra, float rb) {
  return max(a, min(a + ra, rb - abs(b)));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPTONGUE)
// Adds a square ridge ra high and 2 rb wide onto a along the surface of b.
// [bound; L = 1]
float opTongue(float a, float b, float ra, float rb) {
  return min(a, max(a - ra, abs(b) - rb));
}
#endif

// ---- modifiers of one field ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPROUND)
// Grows a shape by r, rounding its convex edges: the r-offset surface.
// [exact outside; L = 1]
float opRound(float d, float r) {
  return d - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPONION)
// A shell of half thickness t around the surface. [exact outside; L = 1]
float opOnion(float d, float t) {
  return abs(d) - t;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPEXTRUDE)
// A solid from a 2D distance d2 (a field of two coordinates of p) extruded
// over [-h, h] along the third, pz: a 2D box distance in (d2, |pz| - h).
// [exact; L = 1]
float opExtrude(float d2, float pz, float h) {
  return msBoxQ(vec2(d2, abs(pz) - h));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPDISPLACE)
// Displaces a surface by a height field h(p) (noise, ripples): d + h. The
// sum of an La- and an Lh-Lipschitz field is (La + Lh)-Lipschitz; with h
// from noise.glsl, L = 1 + amplitude * frequency * the noise's L.
// [bound; L = 1 + Lh]
float opDisplace(float d, float h) {
  return d + h;
}
#endif
