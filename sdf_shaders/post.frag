// post.frag: the post pass. Average of the accumulated samples, then
// tonemap.glsl's outputColor(). The root defines TONEMAP and ENCODE_SRGB.
#pragma once
#include "tonemap.glsl"

uniform sampler2D uAccum;      // sum of samples, RGBA32F
uniform float uInvSamples;     // 1 / samples accumulated
uniform float uExposure;       // linear multiplier
layout(location = 0) out vec4 outColor;

void main() {
  vec4 acc = texelFetch(uAccum, ivec2(gl_FragCoord.xy), 0);
  // A negative alpha: main.frag zeroed a NaN/Inf sample here.
  if (acc.a < 0.0) {
#if FLAG_IN_ALPHA
    // A Shadertoy Image pass already converted each channel: keep them,
    // and mark the pixel for the host's count (it restores alpha 1).
    outColor = vec4(outputColor(acc.rgb * uInvSamples, uExposure), -1.0);
#else
    outColor = nonFiniteOutput();
#endif
    return;
  }
  outColor = vec4(outputColor(acc.rgb * uInvSamples, uExposure), 1.0);
}
