// primitives.glsl: signed distances of 3D shapes (sd*), unsigned ones of
// flat shapes (ud*), and, through primitives2d.glsl, of 2D shapes (sd2*).
// Shapes sit at the origin unless they take points. Move one by evaluating
// it at p - centre; rotate it with domain.glsl's rotations; scale it by s
// as sdX(p / s) * s. All three keep its claim.
//
// Every function's comment ends with its claim, checked by the library
// test (tests/library/, docs/shader-library.md):
//   [exact; L = 1]          the true Euclidean signed distance
//   [exact outside; L = 1]  exact where positive, |f| <= distance inside
//   [bound; L = 1]          |f| <= L * distance everywhere, f = 0 on the surface
//   [unsigned; L = 1]       the exact distance, never negative (flat shapes)
// Each function is guarded by USE_<NAME> (see operators.glsl); a function
// built on another requests it below.
#pragma once
#include "common.glsl"

#if defined(USE_SDHEXPRISM) && !defined(USE_SD2HEXAGON)
#define USE_SD2HEXAGON 1
#endif
#if defined(USE_SDTRIPRISM) && !defined(USE_SD2EQUILATERALTRIANGLE)
#define USE_SD2EQUILATERALTRIANGLE 1
#endif
#if defined(USE_SDRHOMBUS) && !defined(USE_SD2RHOMBUS)
#define USE_SD2RHOMBUS 1
#endif
#if defined(USE_SDPYRAMID) && !defined(USE_UDTRIANGLE)
#define USE_UDTRIANGLE 1
#endif

#include "primitives2d.glsl"

// ---- spheres, planes, boxes ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDSPHERE)
// Sphere of radius r. [exact; L = 1]
float sdSphere(vec3 p, float r) {
  return length(p) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDPLANE)
// Plane dot(p, n) + w, solid on the side n points away from; n of unit
// length (otherwise the field is |n|-Lipschitz). [exact; L = 1]
float sdPlane(vec3 p, vec3 n, float w) {
  return dot(p, n) + w;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDSLAB)
// Slab: the points with x.x <= p.x <= x.y, y.x <= p.y <= y.y and
// z.x <= p.z <= z.y, an axis-aligned box any side of which may be open
// (-BIG or BIG; an axis open both ways is no constraint). Measured from
// each side rather than from a centre, so a side at BIG costs no precision.
// [exact; L = 1]
float sdSlab(vec3 p, vec2 x, vec2 y, vec2 z) {
  return msBoxQ(max(vec3(x.x, y.x, z.x) - p, p - vec3(x.y, y.y, z.y)));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDBOX)
// Axis-aligned box with half extents b. [exact; L = 1]
float sdBox(vec3 p, vec3 b) {
  return msBoxQ(abs(p) - b);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDBOXCHEAP)
// Box with half extents b by the max norm: the nearest face's plane. One
// max, no length; exact inside, too small near edges and corners outside.
// [bound; L = 1]
float sdBoxCheap(vec3 p, vec3 b) {
  return maxComp(abs(p) - b);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDROUNDBOX)
// Box with half extents b (rounding included) and edge radius r,
// 0 <= r <= min(b). [exact; L = 1]
float sdRoundBox(vec3 p, vec3 b, float r) {
  vec3 q = abs(p) - b + r;
  return length(max(q, 0.0)) + min(maxComp(q), 0.0) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDBOXFRAME)
// The 12 edges of a box with half extents b, as square bars 2e thick inside
// it. Folded to one octant it is the union of the three bars meeting at that
// corner; where bars overlap (the corners) the union is a bound inside.
// [exact outside; L = 1]
float sdBoxFrame(vec3 p, vec3 b, float e) {
  vec3 o = abs(p) - b;          // <= 0 inside the outer box, per axis
  vec3 w = abs(o + e) - e;      // <= 0 inside the 2e slab under each face
  return min(min(msBoxQ(vec3(o.x, w.y, w.z)), msBoxQ(vec3(w.x, o.y, w.z))), msBoxQ(vec3(w.x, w.y, o.z)));
}
#endif

// ---- tori ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDTORUS)
// Torus around the y axis: t.x = ring radius, t.y = tube radius (< t.x).
// Swizzle p to stand it up. [exact; L = 1]
float sdTorus(vec3 p, vec2 t) {
  return length(vec2(length(p.xz) - t.x, p.y)) - t.y;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCAPPEDTORUS)
// An arc of a torus in the xy plane: ring radius ra, tube radius rb, the
// arc spanning the angle theta either side of +y with sc = (sin, cos)(theta).
// Where p's direction falls inside the arc the nearest spine point is on the
// circle (law of cosines with k = |p.xy|), else it is the arc's end
// ra * sc (k = dot(p.xy, sc)). [exact; L = 1]
float sdCappedTorus(vec3 p, vec2 sc, float ra, float rb) {
  p.x = abs(p.x);
  float k = sc.y * p.x > sc.x * p.y ? dot(p.xy, sc) : length(p.xy);
  return sqrt(max(dot(p, p) + ra * ra - 2.0 * ra * k, 0.0)) - rb;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDLINK)
// A chain link: a torus in the xy plane (ring radius r1, tube radius r2)
// stretched by le either side of its centre along y, so its spine is a
// stadium. [exact; L = 1]
float sdLink(vec3 p, float le, float r1, float r2) {
  vec3 q = vec3(p.x, max(abs(p.y) - le, 0.0), p.z);
  return length(vec2(length(q.xy) - r1, q.z)) - r2;
}
#endif

// ---- capsules and cylinders ----

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCAPSULE)
// Capsule: the segment a-b swept by radius r; a == b is a sphere (no NaN).
// [exact; L = 1]
float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
  vec3 pa = p - a, ba = b - a;
  float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-12), 0.0, 1.0);
  return length(pa - ba * h) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDVERTICALCAPSULE)
// Capsule from the origin to (0, h, 0), radius r. [exact; L = 1]
float sdVerticalCapsule(vec3 p, float h, float r) {
  p.y -= clamp(p.y, 0.0, h);
  return length(p) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCYLINDER)
// Capped cylinder around the y axis: radius r, half height h (y in [-h, h]).
// [exact; L = 1]
float sdCylinder(vec3 p, float r, float h) {
  return msBoxQ(abs(vec2(length(p.xz), p.y)) - vec2(r, h));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDINFINITECYLINDER)
// Infinite cylinder parallel to y through (c.x, 0, c.y), radius c.z.
// [exact; L = 1]
float sdInfiniteCylinder(vec3 p, vec3 c) {
  return length(p.xz - c.xy) - c.z;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCAPPEDCYLINDER)
// Cylinder of radius r with flat ends at a and b (any axis): the 2D box
// distance in (distance from the axis, position along it). a == b is empty
// but finite. [exact; L = 1]
float sdCappedCylinder(vec3 p, vec3 a, vec3 b, float r) {
  vec3 ba = b - a, pa = p - a;
  float len = max(length(ba), 1e-12);
  vec3 axis = ba / len;
  float t = dot(pa, axis);
  return msBoxQ(vec2(length(pa - axis * t) - r, abs(t - 0.5 * len) - 0.5 * len));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDROUNDEDCYLINDER)
// Cylinder around y of radius r and half height h (rounding included) whose
// two rims are rounded with radius e, 0 <= e <= min(r, h). [exact; L = 1]
float sdRoundedCylinder(vec3 p, float r, float h, float e) {
  return msBoxQ(vec2(length(p.xz), abs(p.y)) - vec2(r, h) + e) - e;
}
#endif

#include "primitives_cones.glsl"
#include "primitives_poly.glsl"
