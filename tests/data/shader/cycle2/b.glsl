// b.glsl
float b_value;
#include "a.glsl"
