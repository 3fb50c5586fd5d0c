// A Shadertoy-style shader that includes one file next to it and one from the shader dir.
#include "lib/palette.glsl"
#include "primitives.glsl"
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  float d = sdSphere(vec3(uv - 0.5, 0.0), 0.25 + 0.01 * float(iFrame));
  fragColor = vec4(palette(uv.x + iTime) * step(d, 0.0) + texture(iChannel0, uv).rgb * iMouse.x, 1.0);
}
