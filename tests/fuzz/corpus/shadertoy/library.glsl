D#include "primitives.glsl"
#include "operators.glsl"
void	mainImage (out vec4 c, in vec2 f) { c = vec4(sdSphere(vec3(f, 0.0), 1.0)); }
