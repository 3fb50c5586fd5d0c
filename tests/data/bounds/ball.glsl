// The bounds check test's ball: its radius is a viewer slider.
uniform float uRadius = 1.0;   // range(0.5, 2.0)
vec2 map(vec3 p) {
  return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), uRadius), MAT_BALL);
}
