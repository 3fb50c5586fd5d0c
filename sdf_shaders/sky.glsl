// sky.glsl: the background seen by rays that hit nothing.
#pragma once

// Horizon -> zenith gradient by the ray's elevation (unit rd). Below the
// horizon it stays the horizon colour, so the ground's far edge fades into it.
vec3 skyColor(vec3 rd) {
  float e = saturate(rd.y);
  return mix(uSkyHorizon, uSkyZenith, sqrt(e) * (2.0 - sqrt(e)));
}

// How far a hit at distance t has faded into the sky: 0 near, 1 at MAX_DIST.
// Hides the hard cut where marching stops (the baseline's horizon seam).
float distanceFade(float t) {
  return smoothstep(FADE_START * float(MAX_DIST), float(MAX_DIST), t);
}
