// shadow.glsl: soft shadows from the distance field, penumbra sized by the light.
#pragma once
#include "aov.glsl"

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
// banding of the classic k*h/t. Steps d / LIPSCHITZ, clamped to
// [SHADOW_MIN_STEP, SHADOW_MAX_STEP]; exits early once fully shadowed; the
// result is smoothstepped (removes the estimator's hard knee at the
// umbra edge).
float softShadowMarch(vec3 ro, vec3 rd, float tmax, float k) {
#if ENABLE_SHADOWS && SHADOW_STEPS > 0
  float res = 1.0;
  float ph = BIG;
  float t = 0.0;
  for (int i = 0; i < SHADOW_STEPS; ++i) {
    float h = map(ro + rd * t).x;
    MS_COUNT_SDF(1);
    MS_COUNT_SHADOW_STEP();
    if (h < float(HIT_EPSILON)) return 0.0;
    float y = h * h / (2.0 * ph);
    float d = sqrt(max(h * h - y * y, 0.0));
    res = min(res, k * d / max(t - y, 1e-6));
    ph = h;
    t += clamp(h / float(LIPSCHITZ), float(SHADOW_MIN_STEP), float(SHADOW_MAX_STEP));
    if (res < 1e-3 || t > tmax) break;
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
