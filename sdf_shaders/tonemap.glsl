// tonemap.glsl: linear radiance -> what an output file stores. Exposure,
// then the tone map (TONEMAP 0 clamp, 1 Reinhard, 2 ACES fit) and the sRGB
// encode for 8-bit outputs (ENCODE_SRGB 1), or exposure-scaled linear (EXR).
// Used by post.frag, and by main.frag when it writes the image itself
// (FUSED_POST 1: one sample per pixel, no accumulation buffer).
#pragma once
#ifndef TONEMAP
#define TONEMAP 2
#endif
#ifndef ENCODE_SRGB
#define ENCODE_SRGB 1
#endif

// Reinhard: x / (1 + x) per channel. Maps [0, inf) onto [0, 1).
vec3 tonemapReinhard(vec3 x) { return x / (1.0 + x); }

// ACES filmic curve, Narkowicz 2015 fit, clamped to [0,1] (without his 0.6
// pre-scale: exposure is the user's knob).
vec3 tonemapAces(vec3 x) {
  const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// Piecewise sRGB encode (IEC 61966-2-1) of linear values in [0,1].
vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  vec3 lo = 12.92 * c;
  vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(lo, hi, step(vec3(0.0031308), c));
}

// The stored value of a pixel whose mean linear radiance is `c` (>= 0).
vec3 outputColor(vec3 c, float exposure) {
  c = max(c * exposure, vec3(0.0));
#if ENCODE_SRGB
#if TONEMAP == 1
  c = tonemapReinhard(c);
#elif TONEMAP == 2
  c = tonemapAces(c);
#endif
  c = encodeSrgb(c);   // TONEMAP 0: the clamp in here is the "tone map"
#endif
  return c;
}

// What a pixel holds when one of its samples was not finite: NaN in every
// channel, so the host's NaN/Inf guard counts it (render/bench --strict).
vec4 nonFiniteOutput() { return vec4(uintBitsToFloat(0x7fc00000u)); }
