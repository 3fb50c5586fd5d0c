// c.glsl
// c.glsl
#include "a.glsl"
