// shadow.glsl: soft shadows from the distance field, penumbra sized by the light.
#pragma once
#include "aov.glsl"
#include "bounds.glsl"

#ifndef SHADOW_ESTIMATOR
#define SHADOW_ESTIMATOR 1     // 1 improved (Aaltonen), 0 classic k*h/t (Quilez)
#endif

// Penumbra sharpness for a light of angular radius theta: k = 1/tan(theta)
// (the estimator reaches 1 where an occluder clears the ray by the light's
// angular radius). Takes tan(theta) directly; 0 (a point or a zero-size
// light) gives k = 1e4, a hard shadow, with no Inf anywhere.
float shadowSharpness(float tanTheta) {
  return 1.0 / max(tanTheta, 1e-4);
}

// Visibility in [0,1] of a light along the unit direction rd from ro (already
// offset off the surface), up to tmax. Improved estimator (Aaltonen, GDC
// 2018): from the previous distance ph and this one h, the closest approach
// of the surface to the ray lies y = h^2/(2 ph) back from t, at distance
// sqrt(h^2 - y^2); penumbra = min(k * that / (t - y)). This removes the
// banding of the classic k*h/t (SHADOW_ESTIMATOR 0 selects the classic one,
// for comparisons). Steps d / LIPSCHITZ, clamped to [SHADOW_MIN_STEP,
// SHADOW_MAX_STEP]; the result is smoothstepped (removes the estimator's hard
// knee at the umbra edge).
//
// Cheap where it can be (bounds.glsl): analytic planes are accounted for in
// closed form first, and only map() is marched; with bounds, only over the
// ray's interval inside the bounding volume grown by the penumbra's reach
// (shadowBoundsPad), so the soft edge outside an object is kept. The ray
// exits early once fully shadowed: a plane in the way, d < HIT_EPSILON, or
// the penumbra below 1e-3.
float softShadowMarch(vec3 ro, vec3 rd, float tmax, float k) {
#if ENABLE_SHADOWS && SHADOW_STEPS > 0
  float res = 1.0;
#if MS_ANALYTIC_PLANES
  res = planesShadow(ro, rd, tmax, k);
  if (res < 1e-3) return 0.0;
#endif
  float t = 0.0, tEnd = tmax;
#if MS_BOUNDS
  vec2 bi = boundsInterval(ro, rd, shadowBoundsPad(ro, tmax, k));
  t = max(t, bi.x);
  tEnd = min(tEnd, bi.y);
#endif
  if (t <= tEnd) {
    float ph = BIG;
    for (int i = 0; i < SHADOW_STEPS; ++i) {
      float h = marchMap(ro + rd * t).x;
      MS_COUNT_SDF(1);
      MS_COUNT_SHADOW_STEP();
      if (h < float(HIT_EPSILON)) return 0.0;
#if SHADOW_ESTIMATOR == 0
      res = min(res, k * h / max(t, 1e-6));
#else
      float y = h * h / (2.0 * ph);
      float d = sqrt(max(h * h - y * y, 0.0));
      res = min(res, k * d / max(t - y, 1e-6));
#endif
      ph = h;
      t += clamp(h / float(LIPSCHITZ), float(SHADOW_MIN_STEP), float(SHADOW_MAX_STEP));
      if (res < 1e-3 || t > tEnd) break;
    }
  }
  res = saturate(res);
  return res * res * (3.0 - 2.0 * res);
#else
  return 1.0;
#endif
}

// The shadow term lighting.glsl uses: softShadowMarch(), plus (only for AOVs
// and debug views) recording the result for the shadow AOV.
float softShadow(vec3 ro, vec3 rd, float tmax, float k) {
  float v = softShadowMarch(ro, rd, tmax, k);
  MS_RECORD_SHADOW(v);
  return v;
}
