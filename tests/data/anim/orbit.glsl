// orbit.glsl: a copy of scenes/seed.glsl (orbit.toml may only include files in its own directory).
// seed.glsl: the founding scene. A unit sphere resting on the plane y = 0.
vec2 map(vec3 p) {
  vec2 ground = vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_FLOOR);
  vec2 ball = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_BALL);
  return opUnion(ground, ball);
}
