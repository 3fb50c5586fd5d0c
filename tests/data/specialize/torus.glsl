// torus.glsl: matte.glsl's materials with a torus instead of the box, for
// the cache-key test (a map that uses another library function).
vec2 map(vec3 p) {
  vec2 ground = vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_FLOOR);
  vec2 ball = vec2(sdSphere(p - vec3(-0.8, 1.0, 0.0), 1.0), MAT_BALL);
  vec2 ring = vec2(sdTorus(p - vec3(1.4, 0.25, -0.4), vec2(0.5, 0.25)), MAT_BLOCK);
  return opUnion(opUnion(ground, ball), ring);
}
