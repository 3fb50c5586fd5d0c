#include "up/secret/secret.glsl"
void mainImage(out vec4 c, in vec2 f) {}
