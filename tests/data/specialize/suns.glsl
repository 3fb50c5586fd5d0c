// suns.glsl: a blob with a smooth bite out of it, over a plane.
vec2 map(vec3 p) {
  vec2 ground = vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_GROUND);
  float blob = opSmoothUnion(sdSphere(p - vec3(0.0, 0.8, 0.0), 0.8),
                             sdSphere(p - vec3(0.6, 1.3, 0.2), 0.5), 0.3);
  blob = opSmoothSubtraction(blob, sdSphere(p - vec3(-0.5, 1.2, -0.6), 0.45), 0.1);
  return opUnion(ground, vec2(blob, MAT_CHROME));
}
