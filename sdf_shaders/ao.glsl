// ao.glsl: ambient occlusion from the distance field alone (Quilez).
#pragma once
#include "aov.glsl"
#include "bounds.glsl"

// Occlusion factor in [0,1] (1 = open) at surface point p with unit normal n.
// AO_TAPS samples at h_i = 0.01 + (AO_RADIUS - 0.01) * i/(AO_TAPS-1) along n:
// occ += (h_i - d(p + h_i n)) * s, s *= 0.95; ao = 1 - 3 * occ, with occ
// rescaled by 5/AO_TAPS so that the darkness does not depend on the tap
// count (the 3 is calibrated for Quilez's 5 taps). p must lie on the surface
// (d(p) ~ 0), otherwise every tap reads as open. Uses the raw field value,
// not d / LIPSCHITZ: it is an estimate, not a safe step. Needs no noise.
float ambientOcclusion(vec3 p, vec3 n) {
#if ENABLE_AO && AO_TAPS > 0
  float occ = 0.0;
  float s = 1.0;
  for (int i = 0; i < AO_TAPS; ++i) {
    float h = 0.01 + (float(AO_RADIUS) - 0.01) * float(i) / float(max(AO_TAPS - 1, 1));
    occ += (h - sceneMap(p + h * n).x) * s;  // planes included
    s *= 0.95;
  }
  MS_COUNT_SDF(AO_TAPS);
  return saturate(1.0 - 3.0 * occ * (5.0 / float(AO_TAPS)));
#else
  return 1.0;
#endif
}
