// stilllife.glsl: a CSG / smooth-union still life on a checkered floor.
// Every piece is exact or a 1-Lipschitz bound, so LIPSCHITZ stays 1. The
// floor is declared in stilllife.toml ([[planes]]) and intersected exactly.
vec2 map(vec3 p) {
  // Rounded box with a sphere carved out of its centre: holes on every face,
  // the cut surface in its own material.
  vec3 qb = p - vec3(-2.3, 0.75, 0.6);
  vec2 box = vec2(sdRoundBox(qb, vec3(0.75), 0.06), MAT_STONE);
  vec2 hole = vec2(sdSphere(qb, 0.95), MAT_INNER);
  vec2 carved = opSubtraction(box, hole);

  // Three spheres melted together.
  float b = opSmoothUnion(sdSphere(p - vec3(0.0, 0.7, 0.2), 0.7),
                          sdSphere(p - vec3(0.55, 1.4, 0.35), 0.45), 0.4);
  b = opSmoothUnion(b, sdSphere(p - vec3(-0.45, 1.25, -0.1), 0.38), 0.4);
  vec2 blob = vec2(b, MAT_BLOB);

  // A ring standing on its edge, facing the camera (xzy swaps y and z: a
  // rotation by a reflection, which keeps the field exact).
  vec2 ring = vec2(sdTorus((p - vec3(2.1, 0.85, 0.9)).xzy, vec2(0.6, 0.25)), MAT_GOLD);

  // A capsule lying on the floor in front.
  vec2 pill = vec2(sdCapsule(p, vec3(0.6, 0.3, -1.6), vec3(2.4, 0.3, -1.0), 0.3), MAT_PLASTIC);

  vec2 d = opUnion(carved, blob);
  d = opUnion(d, ring);
  return opUnion(d, pill);
}
