// modifiers.glsl: the scene graph's one-child nodes (docs/scene-graph.md)
// as functions of the node's local point p: a point map dom*Node run before
// the child, a field map op*Node run on the child's value d after it, and
// for repetitions the copies a point must look at. Each takes the node's
// parameters in the order the graph's vocabulary lists them, the ones the
// builder derives from the child's box last (its radius r, its box lo..hi).
// Claims as in primitives.glsl, for an exact child. Included by
// operators.glsl.
#pragma once
#include "common.glsl"

#if defined(USE_OPTWISTNODE) || defined(USE_OPBENDNODE) || defined(USE_OPSCALENODE)
#ifndef USE_OPBOXFLOOR
#define USE_OPBOXFLOOR 1
#endif
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPBOXFLOOR)
// Outside the box lo..hi, max(d, l * the distance from p to the box); d
// inside it. For a shape inside the box (d >= 0 on the box's sides) that
// is no more than l times its distance, so an l-Lipschitz d stays
// l-Lipschitz with the same zero set and inside, and outside the value
// grows at least as the distance to the box does, which a clamped warp's
// alone does not. [bound; L = l]
float opBoxFloor(float d, vec3 p, vec3 lo, vec3 hi, float l) {
  float e = length(max(max(lo - p, p - hi), vec3(0.0)));
  return e > 0.0 ? max(d, l * e) : d;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMTWISTNODE)
// Twists space about the unit axis by k radians per unit along it, with p
// first pulled in to the cylinder of radius r about the axis (the child's
// box lies within it): within it the twist's Jacobian has largest singular
// value (a + sqrt(a a + 4)) / 2, a = |k| r, and the pull is 1-Lipschitz, so
// the map is that Lipschitz everywhere. lo..hi is the node's box, l its
// bound, for opTwistNode. [bound; L = (a + sqrt(a*a + 4)) / 2 with a = abs(k) r]
vec3 domTwistNode(vec3 p, float k, vec3 axis, float r, float l, vec3 lo, vec3 hi) {
  vec3 along = axis * dot(p, axis), across = p - along;
  float rho = length(across);
  if (rho > r) across *= r / rho;
  float a = k * dot(p, axis), c = cos(a), s = sin(a);
  return along + across * c - cross(axis, across) * s;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPTWISTNODE)
// The twist's value: opBoxFloor over the node's box. [bound; L = l]
float opTwistNode(float d, vec3 p, float k, vec3 axis, float r, float l, vec3 lo, vec3 hi) {
  return opBoxFloor(d, p, lo, hi, l);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMBENDNODE)
// domBend (p.xy turned by k x radians) with p.xy first pulled in to the
// disc of radius r: within it the Jacobian's largest singular value is
// 1 + |k| r. [bound; L = 1 + abs(k) r]
vec3 domBendNode(vec3 p, float k, float r, float l, vec3 lo, vec3 hi) {
  float rho = length(p.xy);
  if (rho > r) p.xy *= r / rho;
  float c = cos(k * p.x), s = sin(k * p.x);
  return vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPBENDNODE)
// The bend's value: opBoxFloor over the node's box. [bound; L = l]
float opBendNode(float d, vec3 p, float k, float r, float l, vec3 lo, vec3 hi) {
  return opBoxFloor(d, p, lo, hi, l);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMSYMMETRYNODE)
// Absolute value on the axes whose entry of `axes` is 1: the shape's part on
// the positive side mirrored onto the negative. A fold: exact for a shape
// on the positive side of those axes, a bound otherwise. [exact; L = 1]
vec3 domSymmetryNode(vec3 p, vec3 axes) {
  return mix(p, abs(p), axes);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMSCALENODE)
// A non-uniform scale by s (> 0): the child's point p / s. [bound; L = 1]
vec3 domScaleNode(vec3 p, vec3 s, float m, vec3 lo, vec3 hi) {
  return p / s;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSCALENODE)
// The child's value times m = min(s), floored by the node's box: it stays
// 1-Lipschitz but may underestimate the distance by up to max(s) / min(s).
// [bound; L = 1]
float opScaleNode(float d, vec3 p, vec3 s, float m, vec3 lo, vec3 hi) {
  return opBoxFloor(d * m, p, lo, hi, 1.0);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPERODE)
// Shrinks a shape by r: the inner r-offset surface, exact inside; outside
// it is below the distance. [bound; L = 1]
float opErode(float d, float r) {
  return d + r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPSHELLNODE)
// A shell of the full thickness around the surface (half inside, half
// outside), as fogleman/sdf's shell. [exact outside; L = 1]
float opShellNode(float d, vec3 p, float thickness) {
  return abs(d) - 0.5 * thickness;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPEXTRUDENODE)
// A 2D field d (of p.xy) extruded over |p.z| <= h / 2 with its edges
// rounded by r (r <= h / 2). [exact; L = 1]
float opExtrudeNode(float d, vec3 p, float h, float r) {
  return msBoxQ(vec2(d + r, abs(p.z) - 0.5 * h + r)) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPEXTRUDEHALFNODE)
// opExtrude's form as a node: over |p.z| <= h. [exact; L = 1]
float opExtrudeHalfNode(float d, vec3 p, float h) {
  return msBoxQ(vec2(d, abs(p.z) - h));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREVOLVENODE)
// The 2D point of a solid of revolution about the y axis: the profile's x
// is the distance from the axis minus offset, its y the height.
// [exact; L = 1]
vec3 domRevolveNode(vec3 p, float offset) {
  return vec3(length(p.xz) - offset, p.y, 0.0);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPBLEND)
// Linear interpolation of two fields, (1 - t) a + t b for t in [0, 1]:
// (1 - t) La + t Lb Lipschitz, and negative only where one of them is.
// [bound; L = 1]
float opBlend(float a, float b, float t) {
  return mix(a, b, t);
}
#endif

// ---- repetitions: a point looks at the copies that may be nearest ----
//
// A copy whose child box (lo..hi, after the builder's slack) is farther
// from p than the nearest value found so far cannot be nearer, so the
// caller skips it (opCopyFloor); these give which copies to look at and
// in what order: the copy p lies in first.

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMREPEATNODE)
// Copies at spacing * j for whole j (within -count..count per axis where
// count >= 0, every j where count < 0; axes of spacing 0 are not
// repeated). Along an axis, copy j + 1 lies wholly beyond copy j from p
// once j spacing + lo >= p, so the copies j in [floor((p - hi) / spacing),
// ceil((p - lo) / spacing)] hold the nearest: the copy t of that range's
// walk, t = 0 the one p is in. Returns p in that copy's frame, and the
// count of copies to look at in n. [exact; L = 1]
vec3 domRepeatNode(vec3 p, vec3 spacing, vec3 count, vec3 lo, vec3 hi, float slack, float t, out float n) {
  vec3 rep = step(1e-30, spacing);
  vec3 sp = mix(vec3(1.0), spacing, rep);
  vec3 jlo = rep * floor((p - hi - slack) / sp), jhi = rep * ceil((p - lo + slack) / sp);
  vec3 lim = mix(vec3(1e9), count, step(0.0, count));
  jlo = clamp(jlo, -lim, lim);
  jhi = clamp(jhi, -lim, lim);
  vec3 c = jhi - jlo + 1.0;
  n = 1.0 + c.x * c.y * c.z;
  vec3 near = clamp(rep * round(p / sp), jlo, jhi), j = near;
  if (t > 0.5) {
    float u = t - 1.0;
    j = jlo + vec3(mod(u, c.x), mod(floor(u / c.x), c.y), floor(u / (c.x * c.y)));
    // The copy of t = 0 again: far away, so the caller's floor skips it.
    if (j == near) return vec3(1e30);
  }
  return p - spacing * j;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_DOMPOLARNODE)
// count copies about the unit axis through the origin, copy k turned by
// 2 pi k / count from the child, which the builder moves out by the radius
// first: p turned back into copy t's frame, t = 0 the copy whose sector
// holds p, and the count of copies to look at in n. `across` is a unit
// vector perpendicular to the axis (the child's offset direction).
// [exact; L = 1]
vec3 domPolarNode(vec3 p, float count, float radius, vec3 axis, vec3 across, vec3 lo, vec3 hi, float slack,
                  float t, out float n) {
  n = count;
  vec3 side = cross(axis, across);
  float a = atan(dot(p, side), dot(p, across));
  float sector = TAU / count;
  float k = floor(a / sector + 0.5) + t;
  float ang = -k * sector;
  float c = cos(ang), s = sin(ang);
  vec3 along = axis * dot(p, axis), off = p - along;
  return along + off * c + cross(axis, off) * s - across * radius;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_OPCOPYFLOOR)
// The least value a copy's field can take at the copy's point q: the
// distance to the child's core box less its slack. [bound; L = 1]
float opCopyFloor(vec3 q, vec3 lo, vec3 hi, float slack) {
  return length(max(max(lo - q, q - hi), vec3(0.0))) - slack;
}
#endif
