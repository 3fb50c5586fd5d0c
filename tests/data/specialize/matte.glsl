// matte.glsl: a sphere and a rounded box on a plane; sdSphere, sdRoundBox,
// sdPlane and opUnion only, so every other library function is left out.
vec2 map(vec3 p) {
  vec2 ground = vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_FLOOR);
  vec2 ball = vec2(sdSphere(p - vec3(-0.8, 1.0, 0.0), 1.0), MAT_BALL);
  vec2 block = vec2(sdRoundBox(p - vec3(1.4, 0.5, -0.4), vec3(0.5), 0.05), MAT_BLOCK);
  return opUnion(opUnion(ground, ball), block);
}
