// seed.glsl: the founding scene. A unit sphere resting on the plane y = 0.
// The plane is declared in seed.toml ([[planes]]) and intersected exactly;
// map() holds only what must be marched.
vec2 map(vec3 p) {
  return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_BALL);
}
