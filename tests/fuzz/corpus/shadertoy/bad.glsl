// Shadertoy shader with a deliberate error after an include.
#include "lib/palette.glsl"
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = vec4(palette(iTime), undefined_MARK_ST);
}
