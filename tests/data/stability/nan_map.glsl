// A scene map that returns NaN for x > 0 (sqrt of a negative number at run
// time): the tracer must read it as empty space (test_nan_guard.cpp).
vec2 map(vec3 p) {
  float d = sdSphere(p, 1.0);
  return vec2(p.x > 0.0 ? sqrt(-1.0 - uTime - abs(p.y)) : d, MAT_BALL);
}
