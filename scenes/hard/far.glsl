// far.glsl (hard case 4): three spheres at ray distances 1e3, 1e4 and 1e5,
// each 0.1 of its distance in radius so all three cover the same screen area.
vec2 map(vec3 p) {
  vec2 res = vec2(sdSphere(p - vec3(-0.45, 0.0, 1.0) * 1e3, 100.0), MAT_NEAR);
  res = opUnion(res, vec2(sdSphere(p - vec3(0.0, 0.0, 1.0) * 1e4, 1e3), MAT_MID));
  return opUnion(res, vec2(sdSphere(p - vec3(0.45, 0.0, 1.0) * 1e5, 1e4), MAT_FAR));
}
