// spot.glsl: one small sphere at the origin, the bloom tests' bright spot
// (tests/cli/test_bloom.cpp). Its material's ambient makes it ~20 in linear
// radiance against a sky of 0.02.
vec2 map(vec3 p) {
  return vec2(sdSphere(p, 0.15), MAT_LAMP);
}
