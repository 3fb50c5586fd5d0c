// includes itself
#include "self.glsl"
