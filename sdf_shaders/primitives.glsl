// primitives.glsl: signed distance functions of basic shapes, centred at the
// origin unless they take points. "Exact" means the value is the true
// Euclidean signed distance, hence 1-Lipschitz and safe to step by in full.
// Move a shape by evaluating it at p - centre; rotate with an orthonormal
// matrix (both keep exactness). Scaling by s: sdX(p / s) * s stays exact.
// Each function is guarded by USE_<NAME> (see operators.glsl).
#pragma once
#include "common.glsl"

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDSPHERE)
// Sphere of radius r. Exact.
float sdSphere(vec3 p, float r) {
  return length(p) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDPLANE)
// Plane dot(p, n) + w with n of unit length (w = offset along -n). Exact when
// |n| = 1; otherwise |n|-Lipschitz (normalize n or divide by |n|).
float sdPlane(vec3 p, vec3 n, float w) {
  return dot(p, n) + w;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDBOX)
// Axis-aligned box with half extents b. Exact inside and outside.
float sdBox(vec3 p, vec3 b) {
  vec3 q = abs(p) - b;
  return length(max(q, 0.0)) + min(maxComp(q), 0.0);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDROUNDBOX)
// Box with half extents b (rounding included) and edge radius r, 0 <= r <= min(b). Exact.
float sdRoundBox(vec3 p, vec3 b, float r) {
  vec3 q = abs(p) - b + r;
  return length(max(q, 0.0)) + min(maxComp(q), 0.0) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDTORUS)
// Torus around the y axis: t.x = major (ring) radius, t.y = minor (tube) radius. Exact.
float sdTorus(vec3 p, vec2 t) {
  vec2 q = vec2(length(p.xz) - t.x, p.y);
  return length(q) - t.y;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCAPSULE)
// Capsule: segment a-b swept by radius r. Exact; a == b degrades to a sphere (no NaN).
float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
  vec3 pa = p - a, ba = b - a;
  float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-12), 0.0, 1.0);
  return length(pa - ba * h) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCYLINDER)
// Capped cylinder around the y axis: radius r, half height h (spans y in [-h, h]). Exact.
float sdCylinder(vec3 p, float r, float h) {
  vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
  return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}
#endif
