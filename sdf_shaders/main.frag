// main.frag: the per-sample pipeline. Primary ray -> trace -> shade ->
// reflections (a loop with a throughput, no recursion) -> linear radiance.
// The root has already included prelude, primitives, operators and the
// scene's map(); this file pulls in the rest of the library.
#pragma once
#ifndef BOUNDS_PROBE
#define BOUNDS_PROBE 0
#endif
// Outside any #if: marchstudio's preprocessor expands an include whatever
// the conditions around it, and #pragma once would then skip the active one.
#include "bounds.glsl"
#if BOUNDS_PROBE
// Not an image: map() on the surface of the scene's [bounds], for the host's
// bounds check (bounds_probe.glsl, app/render/bounds_check.h).
#include "bounds_probe.glsl"
#else
#include "sky.glsl"
#include "camera.glsl"
#include "trace.glsl"
#include "normals.glsl"
#include "shadow.glsl"
#include "ao.glsl"
#include "material.glsl"
#include "lighting.glsl"
#include "aov.glsl"

// FUSED_POST 1: this pass writes the output image itself (tonemap.glsl, with
// the host's TONEMAP and ENCODE_SRGB), so a one-sample frame needs no float
// accumulation buffer and no post pass. Needs one sample per pixel and no AOVs.
#ifndef FUSED_POST
#define FUSED_POST 0
#endif
#if FUSED_POST
#if AOV_OUTPUTS
#error "marchstudio: FUSED_POST writes the image itself and cannot carry AOV outputs"
#endif
#include "tonemap.glsl"
uniform float uExposure;   // linear multiplier (post.frag's, here)
#endif

#if AOV_OUTPUTS
// Extra targets, accumulated additively over samples like outColor (the host
// divides by spp). Layout and miss values: docs/shader-library.md, "AOVs".
layout(location = 1) out vec4 outGeom;  // depth t (world units), N.x, N.y, N.z
layout(location = 2) out vec4 outMisc;  // primary steps, material id, shadow, ao
layout(location = 3) out vec4 outCost;  // shadow steps, reflection steps, map() calls, 1 if primary hit the step cap
#endif
#if DEBUG_VIEW < 0 || DEBUG_VIEW > 6
#error "marchstudio: DEBUG_VIEW must be 0..6 (1 steps, 2 normals, 3 depth, 4 AO, 5 shadow, 6 material)"
#endif

#if MS_CAPTURE
// What the primary ray found, for AOVs and debug views. The per-hit fields
// stay 0 on a miss (and n, shadow, ao on hits lost in the haze, which are not
// shaded), so averaging over samples weights them by coverage.
struct PrimaryAov {
  bool  hit, capped;
  float depth;       // TraceResult.t of the primary ray
  vec3  n;           // the shading normal (after the silhouette tilt)
  int   mat;
  float shadow;      // mean softShadow() over lights with N.L > 0; 1 when there is none
  float ao;
  int   reflSteps;   // steps of all reflection segments
};
PrimaryAov msPrimary = PrimaryAov(false, false, 0.0, vec3(0.0), 0, 0.0, 0.0, 0);
#endif

#if ENABLE_REFLECTIONS && MAX_BOUNCES > 0
#define MS_SEGMENTS (MAX_BOUNCES + 1)   // primary ray + one per bounce
#else
#define MS_SEGMENTS 1
#endif

// Fresnel-Schlick reflectance for F0 and the cosine between normal and viewer.
float fresnelSchlick(float f0, float cosTheta) {
  float m = 1.0 - saturate(cosTheta);
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

// How far secondary rays (shadow, reflection) start off a surface whose pixel
// footprint is `fp` wide: beyond the hit tolerance (so the ray does not
// re-hit the surface it left), still sub-pixel (so shadows do not float).
float surfaceOffset(float fp) {
  return max(10.0 * float(HIT_EPSILON), (float(HIT_TOLERANCE) + 1.0) * fp);
}

// One segment of a sample's path: trace `ray` and add what it finds to
// `radiance`, weighted by `throughput`. A hit adds its local Blinn-Phong
// shading; a mirror scales the throughput by Fresnel F (so local shading gets
// 1 - F) and turns `ray` into the reflected ray. Hits fade into the sky near
// MAX_DIST. Returns false when the path ends: on a miss, once throughput <
// 1e-3, or at the last segment (whose mirror term then reflects the sky only).
bool traceSegment(int seg, inout Ray ray, inout vec3 radiance, inout vec3 throughput, inout int primarySteps) {
  TraceResult tr = trace(ray, 0.0);
  if (seg == 0) primarySteps = tr.steps;
#if MS_CAPTURE
  if (seg == 0) {
    msPrimary.hit = tr.hit;
    msPrimary.capped = tr.capped;
    msPrimary.depth = tr.hit ? tr.t : 0.0;
    msPrimary.mat = tr.hit ? tr.mat : 0;
  } else {
    msPrimary.reflSteps += tr.steps;
  }
#endif
  if (!tr.hit) {
    radiance += throughput * skyColor(ray.d);
    return false;
  }
  float fade = distanceFade(tr.t);
  radiance += throughput * fade * skyColor(ray.d);
  throughput *= 1.0 - fade;
  if (fade > 0.999) return false;   // lost in the haze: skip the shading

  float fp = rayFootprint(ray, tr.t);
  vec3 p = ray.o + ray.d * tr.t;
  // An analytic plane hit has its exact normal (and saves 4 map() calls).
  vec3 n = tr.exact ? tr.n : calcNormal(p, normalEpsilon(p, fp), -ray.d);
  // Snap onto the surface: converged hits stop up to a tolerance short of
  // it, and AO and the checker want the surface itself.
  p -= n * clamp(tr.d, 0.0, fp);
  // Seen from behind only at silhouettes (tolerance hits): tilt the normal
  // until it faces the viewer so lighting and reflection stay sane.
  float nd = dot(n, ray.d);
  if (nd > -1e-3) n = safeNormalize(n - ray.d * (nd + 1e-3), -ray.d);

  vec3 dPdx = transferToSurface(ray.dOdx + tr.t * ray.dDdx, ray.d, n);
  vec3 dPdy = transferToSurface(ray.dOdy + tr.t * ray.dDdy, ray.d, n);
  Surface s = getSurface(tr.mat, p, n, dPdx, dPdy);
  float offset = surfaceOffset(fp);
  float ao = ambientOcclusion(p, n);
  vec3 local = shadeBlinnPhong(s, p, n, -ray.d, ao, offset);
#if MS_CAPTURE
  if (seg == 0) {  // the primary hit's shading cast the sample's first shadow rays
    msPrimary.n = n;
    msPrimary.ao = ao;
    msPrimary.shadow = msShadowCount > 0 ? msShadowSum / float(msShadowCount) : 1.0;
  }
#endif

#if MS_SEGMENTS > 1
  float F = s.f0 > 0.0 ? fresnelSchlick(s.f0, dot(n, -ray.d)) : 0.0;
  if (seg == MS_SEGMENTS - 1) {
    // No bounce left: the sky stands in for what the mirror would show, so
    // a truncated path does not turn grey or black (e.g. at silhouettes).
    radiance += throughput * mix(local, skyColor(reflect(ray.d, n)), F);
    return false;
  }
  radiance += throughput * (1.0 - F) * local;
  throughput *= F;
  if (maxComp(throughput) < 1e-3) return false;
  // Reflect the ray and its differentials (flat-mirror transfer, Igehy;
  // surface curvature ignored).
  ray.o = p + n * offset;
  ray.d = reflect(ray.d, n);
  ray.dOdx = dPdx;
  ray.dOdy = dPdy;
  ray.dDdx = reflect(ray.dDdx, n);
  ray.dDdy = reflect(ray.dDdy, n);
  // A reflected ray that can hit nothing sees the sky: add it here and end
  // the path. Same radiance as tracing it, but a block of pixels whose rays
  // all escape leaves the segment loop instead of running the whole segment
  // body again (SIMD lanes, and llvmpipe, pay for a body any lane runs).
  if (rayEscapes(ray.o, ray.d)) {
    radiance += throughput * skyColor(ray.d);
    return false;
  }
  return true;
#else
  radiance += throughput * local;
  return false;
#endif
}

// Radiance of one sample: the primary ray, then one segment per mirror
// bounce. With nothing to reflect (MS_SEGMENTS 1, e.g. a specialized scene
// without mirrors) there is no loop at all.
vec3 renderSample(vec2 pix, out int primarySteps) {
  Ray ray = cameraRay(pix);
  vec3 radiance = vec3(0.0);
  vec3 throughput = vec3(1.0);
  primarySteps = 0;
#if MS_SEGMENTS > 1
  for (int seg = 0; seg < MS_SEGMENTS; ++seg)
    if (!traceSegment(seg, ray, radiance, throughput, primarySteps)) break;
#else
  traceSegment(0, ray, radiance, throughput, primarySteps);
#endif
  return radiance;
}

#if DEBUG_VIEW
// The debug view's value, shown as it is (the viewer's post pass for a debug
// view has no exposure, tone map or sRGB encode). Misses
// are black except in the steps view, where their steps are real cost.
vec3 debugViewColor(int primarySteps) {
  PrimaryAov a = msPrimary;
#if DEBUG_VIEW == 1
  return stepsHeat(float(primarySteps));
#elif DEBUG_VIEW == 2
  return dot(a.n, a.n) > 0.0 ? 0.5 * a.n + 0.5 : vec3(0.0);
#elif DEBUG_VIEW == 3
  return a.hit ? vec3(depthShade(a.depth)) : vec3(0.0);
#elif DEBUG_VIEW == 4
  return vec3(a.ao);
#elif DEBUG_VIEW == 5
  return vec3(a.shadow);
#else
  return a.hit ? materialColor(a.mat) : vec3(0.0);
#endif
}
#endif

void main() {
  int primarySteps;  // kept for the step-count AOV
  // The pixel in the whole image: a tile's framebuffer starts at its offset.
  vec3 c = renderSample(floor(gl_FragCoord.xy) + uPixelOffset + uJitter, primarySteps);
  // Last line of defence: the pipeline guards its divisions, but a user map()
  // may not; a NaN would poison the whole accumulation buffer. The sample is
  // zeroed but flagged, so the host's NaN/Inf guard (render/bench --strict)
  // still sees it: a negative colour alpha (post.frag turns the pixel NaN),
  // or with AOVs a NaN depth.
  bool nonFinite = notFinite(c);
  if (nonFinite) c = vec3(0.0);
#if DEBUG_VIEW
  c = debugViewColor(primarySteps);
#endif
#if AOV_OUTPUTS
  // Alpha carries hit coverage here (post ignores the accumulated alpha and
  // writes 1), so accumulated alpha / spp = the fraction of samples that hit.
  outColor = vec4(max(c, vec3(0.0)), msPrimary.hit ? 1.0 : 0.0);
  outGeom = vec4(nonFinite ? uintBitsToFloat(0x7fc00000u) : msPrimary.depth, msPrimary.n);
  outMisc = vec4(float(primarySteps), float(msPrimary.mat), msPrimary.shadow, msPrimary.ao);
#if MS_COST_PRIMS  // bench's second counting pass of a graph scene: primitives instead of map() calls
  outCost = vec4(float(msShadowSteps), float(msPrimary.reflSteps), float(msPrimEvals),
                 msPrimary.capped ? 1.0 : 0.0);
#else
  outCost = vec4(float(msShadowSteps), float(msPrimary.reflSteps), float(msSdfEvals),
                 msPrimary.capped ? 1.0 : 0.0);
#endif
#elif FUSED_POST
  outColor = nonFinite ? nonFiniteOutput() : vec4(outputColor(max(c, vec3(0.0)), uExposure), 1.0);
#else
  outColor = vec4(max(c, vec3(0.0)), nonFinite ? -1.0 : 0.0);  // post ignores alpha but its sign
#endif
}
#endif  // BOUNDS_PROBE
