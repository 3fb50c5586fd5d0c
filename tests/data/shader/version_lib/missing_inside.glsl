// fine so far
#include "not_there.glsl"
