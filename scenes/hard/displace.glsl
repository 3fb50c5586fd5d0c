// displace.glsl (hard case 6): a unit sphere with a sine displacement of
// amplitude 0.1 and frequency 10. The displacement's gradient is at most
// 0.1 * 10 * sqrt(3) = 1.73, so the field is 2.73-Lipschitz; displace.toml
// declares lipschitz = 3.
vec2 map(vec3 p) {
  float disp = 0.1 * sin(10.0 * p.x) * sin(10.0 * p.y) * sin(10.0 * p.z);
  return vec2(sdSphere(p, 1.0) + disp, MAT_SHAPE);
}
