// Test scene: a ball on a floor.
#include "primitives.glsl"
vec2 map(vec3 p) {
  return opU(vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), float(MAT_BALL_2)), vec2(p.y, float(MAT_FLOOR)));
}
