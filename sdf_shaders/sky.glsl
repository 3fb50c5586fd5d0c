// sky.glsl: the background seen by rays that hit nothing.
#pragma once

#ifndef ENV_MAP
#define ENV_MAP 0              // 1: [sky] environment, an equirectangular HDR map (render/environment.h)
#endif

#if ENV_MAP
layout(binding = 0) uniform sampler2D uEnvMap;  // row 0 (v = 0) is +y; the centre column faces +z
uniform mat3 uEnvRotation;     // world -> map directions ([sky] rotation about +y)
uniform float uEnvIntensity;
uniform vec3 uEnvSH[9];        // the map's irradiance E(n)/pi, band 2 (already times intensity)

// The map seen along unit rd: no derivatives (textureLod), so the compute
// path and tiles see the same texels.
vec3 skyColor(vec3 rd) {
  vec3 d = uEnvRotation * rd;
  vec2 uv = vec2(0.5 + atan(d.x, d.z) * (0.5 / PI), acos(clamp(d.y, -1.0, 1.0)) * (1.0 / PI));
  return textureLod(uEnvMap, uv, 0.0).rgb * uEnvIntensity;
}

// Diffuse light from the whole map arriving at a surface with unit normal
// n, over pi: the ambient term's Ia. Evaluates render/environment.cpp's basis.
vec3 envIrradiance(vec3 n) {
  vec3 d = uEnvRotation * n;
  vec3 e = uEnvSH[0] * 0.282095
         + 0.488603 * (uEnvSH[1] * d.y + uEnvSH[2] * d.z + uEnvSH[3] * d.x)
         + 1.092548 * (uEnvSH[4] * d.x * d.y + uEnvSH[5] * d.y * d.z + uEnvSH[7] * d.x * d.z)
         + uEnvSH[6] * (0.315392 * (3.0 * d.z * d.z - 1.0))
         + uEnvSH[8] * (0.546274 * (d.x * d.x - d.y * d.y));
  return max(e, vec3(0.0));
}
#else
// Horizon -> zenith gradient by the ray's elevation (unit rd). Below the
// horizon it stays the horizon colour, so the ground's far edge fades into it.
vec3 skyColor(vec3 rd) {
  float e = saturate(rd.y);
  return mix(uSkyHorizon, uSkyZenith, sqrt(e) * (2.0 - sqrt(e)));
}
#endif

// How far a hit at distance t has faded into the sky: 0 near, 1 at MAX_DIST.
// Hides the hard cut where marching stops (the baseline's horizon seam).
float distanceFade(float t) {
  return smoothstep(FADE_START * float(MAX_DIST), float(MAX_DIST), t);
}
