#include "lib.glsl"
float once_user() { return once_lib(); }
