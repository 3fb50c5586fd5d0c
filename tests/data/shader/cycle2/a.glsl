// a.glsl
#include "b.glsl"
