// bounds.glsl: what a scene declares besides map(). Analytic planes
// ([[planes]] in the scene file) are intersected exactly and never marched;
// a bounding volume ([bounds]) limits where map() is marched. The host passes
// both as defines (app/shader/assemble.cpp); each has a default here, so a
// root without them means no planes and no bounds, as before.
//   NUM_PLANES        number of planes (0..8)
//   PLANE_LIST        NUM_PLANES vec4s: xyz the unit normal n, w the offset; the
//                     plane is dot(p, n) + w = 0, solid below (as sdPlane)
//   PLANE_MATERIALS   NUM_PLANES material ids
//   ANALYTIC_PLANES   1: intersect the planes exactly; 0: march them as part of
//                     the field, the textbook way (the baseline, for comparison)
//   BOUNDS_KIND       0 none; 1 sphere: BOUNDS_A = vec4(centre, radius);
//                     2 box: BOUNDS_A = vec4(min, 0), BOUNDS_B = vec4(max, 0)
//   BOUNDS_UNIFORMS   1: BOUNDS_A and BOUNDS_B are the uniforms uBoundsA and
//                     uBoundsB instead (the viewer, for a scene graph's box)
//   OMEGA             over-relaxation factor of the primary/reflection march (trace.glsl)
#pragma once
#include "common.glsl"

#if defined(BOUNDS_UNIFORMS) && BOUNDS_UNIFORMS
// As BOUNDS_A and BOUNDS_B would hold them; app/render/uniforms.cpp sets both.
uniform vec4 uBoundsA;
uniform vec4 uBoundsB;
#define BOUNDS_A uBoundsA
#define BOUNDS_B uBoundsB
#endif

#ifndef NUM_PLANES
#define NUM_PLANES 0
#endif
#ifndef ANALYTIC_PLANES
#define ANALYTIC_PLANES 1
#endif
#ifndef BOUNDS_KIND
#define BOUNDS_KIND 0
#endif
#ifndef OMEGA
#define OMEGA 1.0
#endif
// Analytic work only when there is something analytic to do.
#if NUM_PLANES > 0 && ANALYTIC_PLANES
#define MS_ANALYTIC_PLANES 1
#else
#define MS_ANALYTIC_PLANES 0
#endif
// The bounds hold map()'s objects, not the planes: with the planes marched
// (the textbook way) every ray must march everywhere, so they do not apply.
#if BOUNDS_KIND != 0 && (NUM_PLANES == 0 || ANALYTIC_PLANES)
#define MS_BOUNDS 1
#else
#define MS_BOUNDS 0
#endif

#if NUM_PLANES > 0
const vec4 kPlanes[NUM_PLANES] = vec4[NUM_PLANES](PLANE_LIST);
const int kPlaneMaterials[NUM_PLANES] = int[NUM_PLANES](PLANE_MATERIALS);
#endif

// The declared planes as one signed field with material id (BIG when none).
// Exact: each plane is the true distance to its half-space.
vec2 planesMap(vec3 p) {
  vec2 res = vec2(BIG, 0.0);
#if NUM_PLANES > 0
  for (int i = 0; i < NUM_PLANES; ++i) {
    float d = dot(p, kPlanes[i].xyz) + kPlanes[i].w;
    if (d < res.x) res = vec2(d, float(kPlaneMaterials[i]));
  }
#endif
  return res;
}

// The whole scene's field: map() and the planes. Normals and AO read this,
// so they are the same whether the planes are marched or intersected.
vec2 sceneMap(vec3 p) {
#if NUM_PLANES > 0
  vec2 a = map(p), b = planesMap(p);
  return a.x < b.x ? a : b;  // opUnion, inline: the library may be pruned to what map() uses
#else
  return map(p);
#endif
}

// The field the marchers (trace, soft shadows) step through: map() alone
// when the planes are analytic, else the whole scene.
vec2 marchMap(vec3 p) {
#if MS_ANALYTIC_PLANES
  return map(p);
#else
  return sceneMap(p);
#endif
}

// The nearest plane the ray o + t d (unit d) meets in [tmin, tmax]. On a hit
// returns true and shortens tmax to it, with the material and the normal. An
// origin already on the solid side hits at tmin, as marching would.
bool intersectPlanes(vec3 o, vec3 d, float tmin, inout float tmax, out int mat, out vec3 n) {
  bool hit = false;
  mat = 0;
  n = vec3(0.0, 1.0, 0.0);
#if NUM_PLANES > 0
  for (int i = 0; i < NUM_PLANES; ++i) {
    vec3 pn = kPlanes[i].xyz;
    float dn = dot(d, pn);
    float h = dot(o, pn) + kPlanes[i].w + tmin * dn;  // signed height at tmin
    float t = h <= 0.0 ? tmin : (dn < 0.0 ? tmin - h / dn : BIG);
    if (t <= tmax) {
      tmax = t;
      mat = kPlaneMaterials[i];
      n = pn;
      hit = true;
    }
  }
#endif
  return hit;
}

// Soft-shadow factor of the planes alone for a shadow ray from ro along unit
// rd up to tmax, penumbra sharpness k: the classic k h(t) / t. A plane's
// height h(t) = h0 + t dn is linear, so h(t)/t falls monotonically and its
// minimum over the ray is at tmax: exact, no marching. 0 when the ray enters
// a plane before tmax (or starts inside one).
float planesShadow(vec3 ro, vec3 rd, float tmax, float k) {
  float res = 1.0;
#if NUM_PLANES > 0
  float tm = max(tmax, 1e-6);
  for (int i = 0; i < NUM_PLANES; ++i) {
    float h0 = dot(ro, kPlanes[i].xyz) + kPlanes[i].w;
    float h1 = h0 + tm * dot(rd, kPlanes[i].xyz);
    if (h0 <= 0.0 || h1 <= 0.0) return 0.0;
    res = min(res, k * h1 / tm);
  }
#endif
  return res;
}

// [t0, t1] where the ray o + t d (unit d) is inside the bounding volume grown
// by `pad`; t0 > t1 when it misses. Without bounds: (-BIG, BIG).
vec2 boundsInterval(vec3 o, vec3 d, float pad) {
#if BOUNDS_KIND == 1
  vec3 oc = o - BOUNDS_A.xyz;
  float r = BOUNDS_A.w + pad;
  float b = dot(oc, d);
  float disc = b * b - (dot(oc, oc) - r * r);
  if (disc < 0.0) return vec2(BIG, -BIG);
  float s = sqrt(disc);
  return vec2(-b - s, -b + s);
#elif BOUNDS_KIND == 2
  // Slabs; a zero direction component becomes tiny, never a division by 0.
  vec3 sgn = vec3(d.x < 0.0 ? -1.0 : 1.0, d.y < 0.0 ? -1.0 : 1.0, d.z < 0.0 ? -1.0 : 1.0);
  vec3 inv = sgn / max(abs(d), vec3(1e-20));
  vec3 ta = (BOUNDS_A.xyz - pad - o) * inv, tb = (BOUNDS_B.xyz + pad - o) * inv;
  vec3 lo = min(ta, tb), hi = max(ta, tb);
  return vec2(maxComp(lo), min(min(hi.x, hi.y), hi.z));
#else
  return vec2(-BIG, BIG);
#endif
}

// True when the ray o + t d (unit d, t >= 0) can hit nothing: it meets no
// analytic plane before MAX_DIST and misses the bounding volume. Exactly the
// rays trace() returns as misses without a step; false without bounds.
bool rayEscapes(vec3 o, vec3 d) {
#if MS_BOUNDS
  float tEnd = float(MAX_DIST);
  int mat;
  vec3 n;
#if MS_ANALYTIC_PLANES
  if (intersectPlanes(o, d, 0.0, tEnd, mat, n)) return false;
#endif
  vec2 bi = boundsInterval(o, d, 0.0);
  return max(bi.x, 0.0) > min(bi.y, tEnd);
#else
  return false;
#endif
}

// How far beyond the bounds a shadow ray from ro, up to tmax, can still see
// a penumbra from a light of sharpness k. The field is at least the
// distance h to the bounds, and the estimator stays at 1 while
// k h / t >= 1, i.e. h >= t / k. With T = min(tmax, |ro - c| + R) (c, R:
// the bounds' bounding sphere), every point nearer than T / (k - 1) to the
// geometry lies within t <= T k / (k - 1) of ro, so pad = T / (k - 1)
// suffices; doubled for the improved estimator, whose closest-approach
// distance can be below h. Lights so large that k <= 2 get no clipping.
float shadowBoundsPad(vec3 ro, float tmax, float k) {
#if BOUNDS_KIND == 1
  vec3 c = BOUNDS_A.xyz;
  float R = BOUNDS_A.w;
#elif BOUNDS_KIND == 2
  vec3 c = 0.5 * (BOUNDS_A.xyz + BOUNDS_B.xyz);
  float R = 0.5 * length(BOUNDS_B.xyz - BOUNDS_A.xyz);
#else
  vec3 c = vec3(0.0);
  float R = 0.0;
#endif
  return k <= 2.0 ? BIG : 2.0 * min(tmax, length(ro - c) + R) / (k - 1.0);
}
