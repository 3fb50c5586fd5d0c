// b.glsl
#include "c.glsl"
