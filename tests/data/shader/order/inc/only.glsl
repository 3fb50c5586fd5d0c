// only.glsl lives in include dir 1 and includes y.glsl
#include "y.glsl"
