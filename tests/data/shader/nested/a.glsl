// a.glsl: level 1
float a_value() { return 1.0; }
#include "sub/b.glsl"
float a_after() { return 2.0; }
