// bloom_blur.frag: one direction of a separable Gaussian blur of the bloom
// target (docs/post.md). Taps -uHalf..uHalf along uDir, weights
// exp(-i^2 / (2 sigma^2)) normalised to sum 1; texels past the edge repeat
// the edge one (clamp to edge). The weights are symmetric and each pair
// (p + i, p - i) is added before it is weighted, so a symmetric image stays
// exactly symmetric.
#pragma once

uniform sampler2D uSrc;  // the other bloom target
uniform ivec2 uDir;      // (1, 0) horizontal, (0, 1) vertical
uniform float uSigma;    // in this target's pixels
uniform int uHalf;       // taps on each side
layout(location = 0) out vec4 outColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uSrc, 0) - 1;
  vec3 sum = texelFetch(uSrc, p, 0).rgb;
  float wsum = 1.0;
  float k = -0.5 / (uSigma * uSigma);
  for (int i = 1; i <= uHalf; ++i) {
    float w = exp(k * float(i * i));
    vec3 a = texelFetch(uSrc, clamp(p + i * uDir, ivec2(0), last), 0).rgb;
    vec3 b = texelFetch(uSrc, clamp(p - i * uDir, ivec2(0), last), 0).rgb;
    sum += w * (a + b);
    wsum += 2.0 * w;
  }
  outColor = vec4(sum / wsum, 1.0);
}
