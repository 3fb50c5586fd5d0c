// bloom_extract.frag: the first bloom pass (docs/post.md). Each pixel of the
// reduced-resolution target is the box average, over the full-resolution
// pixels it covers, of what each pixel's mean linear radiance has above the
// threshold: c * max(L - threshold, 0) / L, L its Rec. 709 luminance. A box
// and not one tap, so a bright spot smaller than a target pixel still blooms.
#pragma once

uniform sampler2D uAccum;   // sum of samples, RGBA32F, full resolution
uniform float uInvSamples;  // 1 / samples accumulated
uniform float uThreshold;   // linear radiance
uniform ivec2 uSrcSize;     // the accumulation buffer's size
uniform ivec2 uDstSize;     // this target's size
layout(location = 0) out vec4 outColor;

void main() {
  ivec2 dst = ivec2(gl_FragCoord.xy);
  ivec2 lo = (dst * uSrcSize) / uDstSize;
  ivec2 hi = max(((dst + 1) * uSrcSize) / uDstSize, lo + 1);
  vec3 sum = vec3(0.0);
  for (int y = lo.y; y < hi.y; ++y) {
    for (int x = lo.x; x < hi.x; ++x) {
      vec4 acc = texelFetch(uAccum, ivec2(x, y), 0);
      if (acc.a < 0.0) continue;  // a non-finite sample was zeroed here: it adds no light
      vec3 c = max(acc.rgb * uInvSamples, vec3(0.0));
      float l = dot(c, vec3(0.2126, 0.7152, 0.0722));
      if (l > uThreshold) sum += c * ((l - uThreshold) / l);
    }
  }
  vec2 n = vec2(hi - lo);
  outColor = vec4(sum / (n.x * n.y), 1.0);
}
