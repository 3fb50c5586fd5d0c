// post.frag: the post pass. Average of the accumulated samples, then
// tonemap.glsl's outputColor(). The root defines TONEMAP and ENCODE_SRGB,
// and BLOOM 1 when the bloom passes ran (render/bloom.h): their blurred
// target, upsampled bilinearly, is added to the mean before exposure.
#pragma once
#include "tonemap.glsl"

uniform sampler2D uAccum;      // sum of samples, RGBA32F
uniform float uInvSamples;     // 1 / samples accumulated
uniform float uExposure;       // linear multiplier
layout(location = 0) out vec4 outColor;
#if BLOOM
uniform sampler2D uBloom;      // blurred bright parts, reduced resolution, linear filtering
uniform float uBloomIntensity;
#endif

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
#if BLOOM
  vec2 uv = gl_FragCoord.xy / vec2(textureSize(uAccum, 0));
  outColor = vec4(outputColor(acc.rgb * uInvSamples + uBloomIntensity * texture(uBloom, uv).rgb, uExposure), 1.0);
#else
  outColor = vec4(outputColor(acc.rgb * uInvSamples, uExposure), 1.0);
#endif
}
