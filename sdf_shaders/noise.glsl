// noise.glsl: lattice noises for terrain and surface detail (noise*), each
// in [-1, 1] with a Lipschitz bound L that holds for every hash: the worst
// case over the lattice's random values or gradients, computed by
// tools/noise-bounds.cpp (+1%). A height field a * noiseX(p * f) is
// (a f L)-Lipschitz; a terrain y - h(x, z) then has
// L = sqrt(1 + (a f L)^2), to be written into [quality] lipschitz.
// Claims: [noise; L = ...], checked by the library test.
#pragma once
#include "common.glsl"

#if defined(USE_NOISEFBM) && !defined(USE_NOISEVALUE)
#define USE_NOISEVALUE 1
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_NOISEVALUE) || defined(USE_NOISEGRADIENT) || defined(USE_NOISESIMPLEX)
// pcg3d (Jarzynski and Olano 2020): a well-mixed hash of a lattice point.
uvec3 msHash3(ivec3 c) {
  uvec3 v = uvec3(c) * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  return v;
}
// A value in [-1, 1) per lattice point.
float msHashValue(ivec3 c) { return float(msHash3(c).x >> 8u) * (2.0 / 16777216.0) - 1.0; }
// The ramp dot(g, d) of lattice point c's unit gradient g at offset d, g
// picked by the hash's top bits with selects (no table: a dynamically
// indexed constant array is slow on llvmpipe). 2D: one of the 8 directions
// of the axes and diagonals. 3D: one of the 12 cube edge directions
// (1, 1, 0) / sqrt 2 ..., 16 cases with 4 repeated, as in Perlin's
// improved noise.
float msRamp(ivec2 c, vec2 d) {
  uint h = msHash3(ivec3(c, 0)).x >> 29u;
  vec2 s = vec2((h & 1u) != 0u ? -1.0 : 1.0, (h & 2u) != 0u ? -1.0 : 1.0);
  if ((h & 4u) != 0u) return dot(s, d) * 0.70710678;
  return (h & 1u) != 0u ? s.y * d.x : s.y * d.y;
}
float msRamp(ivec3 c, vec3 d) {
  uint h = msHash3(c).x >> 28u;
  float u = h < 8u ? d.x : d.y;
  float v = h < 4u ? d.y : (h == 12u || h == 14u ? d.x : d.z);
  return (((h & 1u) == 0u ? u : -u) + ((h & 2u) == 0u ? v : -v)) * 0.70710678;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_NOISEVALUE)
// Value noise: random lattice values blended with the cubic Hermite fade
// (slope at most 1.5). [noise; L = 3.03]
float noiseValue(vec2 p) {
  ivec2 c = ivec2(floor(p));
  vec2 f = p - floor(p), u = f * f * (3.0 - 2.0 * f);
  float v00 = msHashValue(ivec3(c, 0)), v10 = msHashValue(ivec3(c + ivec2(1, 0), 0));
  float v01 = msHashValue(ivec3(c + ivec2(0, 1), 0)), v11 = msHashValue(ivec3(c + ivec2(1, 1), 0));
  return mix(mix(v00, v10, u.x), mix(v01, v11, u.x), u.y);
}
float noiseValue(vec3 p) {
  ivec3 c = ivec3(floor(p));
  vec3 f = p - floor(p), u = f * f * (3.0 - 2.0 * f);
  const ivec2 o = ivec2(0, 1);
  float a = mix(msHashValue(c + o.xxx), msHashValue(c + o.yxx), u.x);
  float b = mix(msHashValue(c + o.xyx), msHashValue(c + o.yyx), u.x);
  float d = mix(msHashValue(c + o.xxy), msHashValue(c + o.yxy), u.x);
  float e = mix(msHashValue(c + o.xyy), msHashValue(c + o.yyy), u.x);
  return mix(mix(a, b, u.y), mix(d, e, u.y), u.z);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_NOISEGRADIENT)
// Gradient (Perlin) noise: lattice ramps g.(p - c) blended with the
// quintic fade, divided by their largest sum (sqrt(D) / 2), so it spans
// [-1, 1]. 2D: L = 2.96; 3D: L = 3.26. [noise; L = 3.26]
float noiseGradient(vec2 p) {
  ivec2 c = ivec2(floor(p));
  vec2 f = p - floor(p), u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  float a = msRamp(c, f), b = msRamp(c + ivec2(1, 0), f - vec2(1, 0));
  float d = msRamp(c + ivec2(0, 1), f - vec2(0, 1)), e = msRamp(c + ivec2(1, 1), f - vec2(1, 1));
  return 1.41421356 * mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}
float noiseGradient(vec3 p) {
  ivec3 c = ivec3(floor(p));
  vec3 f = p - floor(p), u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  const ivec2 o = ivec2(0, 1);
  float a = mix(msRamp(c + o.xxx, f - vec3(o.xxx)), msRamp(c + o.yxx, f - vec3(o.yxx)), u.x);
  float b = mix(msRamp(c + o.xyx, f - vec3(o.xyx)), msRamp(c + o.yyx, f - vec3(o.yyx)), u.x);
  float d = mix(msRamp(c + o.xxy, f - vec3(o.xxy)), msRamp(c + o.yxy, f - vec3(o.yxy)), u.x);
  float e = mix(msRamp(c + o.xyy, f - vec3(o.xyy)), msRamp(c + o.yyy, f - vec3(o.yyy)), u.x);
  return 1.15470054 * mix(mix(a, b, u.y), mix(d, e, u.y), u.z);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_NOISESIMPLEX)
// Simplex noise: ramps of the D + 1 corners of the skewed simplex around p,
// each under the kernel (0.5 - |d|^2)^4 (0.5: zero at the simplex's far
// side, so continuous), divided by the largest sum. Spikier than gradient
// noise for its range. 2D: L = 7.43; 3D: L = 7.88. [noise; L = 7.88]
float noiseSimplex(vec2 p) {
  const float F = 0.36602540, G = 0.21132487;   // (sqrt 3 - 1) / 2, (3 - sqrt 3) / 6
  vec2 i = floor(p + (p.x + p.y) * F);
  vec2 x0 = p - i + (i.x + i.y) * G;
  vec2 o = x0.x > x0.y ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
  vec2 d[3] = vec2[](x0, x0 - o + G, x0 - 1.0 + 2.0 * G);
  vec2 k[3] = vec2[](vec2(0.0), o, vec2(1.0));
  float n = 0.0;
  for (int j = 0; j < 3; ++j) {
    float a = max(0.5 - dot(d[j], d[j]), 0.0);
    n += a * a * a * a * msRamp(ivec2(i + k[j]), d[j]);
  }
  return n * (1.0 / 0.0100802);
}
float noiseSimplex(vec3 p) {
  const float F = 1.0 / 3.0, G = 1.0 / 6.0;
  vec3 i = floor(p + dot(p, vec3(F)));
  vec3 x0 = p - i + dot(i, vec3(G));
  vec3 g = step(x0.yzx, x0.xyz), l = 1.0 - g;
  vec3 i1 = min(g, l.zxy), i2 = max(g, l.zxy);
  vec3 d[4] = vec3[](x0, x0 - i1 + G, x0 - i2 + 2.0 * G, x0 - 1.0 + 3.0 * G);
  vec3 k[4] = vec3[](vec3(0.0), i1, i2, vec3(1.0));
  float n = 0.0;
  for (int j = 0; j < 4; ++j) {
    float a = max(0.5 - dot(d[j], d[j]), 0.0);
    n += a * a * a * a * msRamp(ivec3(i + k[j]), d[j]);
  }
  return n * (1.0 / 0.0092891);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_NOISEFBM)
// Fractal sum of `octaves` value noises, each at twice the frequency
// (turned, to hide the lattice) and `gain` times the amplitude of the last,
// divided by the amplitudes' sum: in [-1, 1] with
// L = 3.03 * sum_i (2 gain)^i / sum_i gain^i (noiseFbmLipschitz).
// [noise; L = 3.03 * sum (2 gain)^i / sum gain^i]
float noiseFbm(vec2 p, int octaves, float gain) {
  const mat2 turn = mat2(0.8, 0.6, -0.6, 0.8);
  float sum = 0.0, amp = 1.0, norm = 0.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * noiseValue(p);
    norm += amp;
    amp *= gain;
    p = turn * p * 2.0 + vec2(7.31, 1.73);
  }
  return sum / norm;
}
float noiseFbm(vec3 p, int octaves, float gain) {
  const mat3 turn = mat3(0.0, -0.8, -0.6, 0.8, 0.36, -0.48, 0.6, -0.48, 0.64);
  float sum = 0.0, amp = 1.0, norm = 0.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * noiseValue(p);
    norm += amp;
    amp *= gain;
    p = turn * p * 2.0 + vec3(7.31, 1.73, 4.19);
  }
  return sum / norm;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_NOISEFBMLIPSCHITZ)
// noiseFbm's Lipschitz bound for these octaves and gain. [helper]
float noiseFbmLipschitz(int octaves, float gain) {
  float s = 0.0, norm = 0.0, amp = 1.0, freq = 1.0;
  for (int i = 0; i < octaves; ++i) {
    s += amp * freq;
    norm += amp;
    amp *= gain;
    freq *= 2.0;
  }
  return 3.03 * s / norm;
}
#endif
