// columns.glsl: a colonnade. Two rows of nine columns (limited domain
// repetition along x, the second row a mirror image in z), an architrave on
// each row, a mirror orb in the middle, all on a checkered floor (declared
// in columns.toml as a plane and intersected exactly, not marched).
// Each column fits inside its 3-unit cell and is symmetric, so the repeated
// field stays exact; LIPSCHITZ stays 1.

// One column at the origin of its cell, standing on y = 0.
vec2 column(vec3 q) {
  float shaft = sdCylinder(q - vec3(0.0, 2.2, 0.0), 0.35, 1.8);
  float base = sdRoundBox(q - vec3(0.0, 0.2, 0.0), vec3(0.55, 0.2, 0.55), 0.03);
  float capital = sdRoundBox(q - vec3(0.0, 4.15, 0.0), vec3(0.55, 0.15, 0.55), 0.03);
  return opUnion(vec2(shaft, MAT_MARBLE), vec2(min(base, capital), MAT_STONE));
}

vec2 map(vec3 p) {
  // Fold z so both rows are one row at z = +2.5, then repeat along x.
  vec3 q = vec3(p.x, p.y, abs(p.z) - 2.5);
  vec3 c = q;
  c.x = domRepeatLimited(q.x, 3.0, 4.0);
  vec2 cols = column(c);

  vec2 beam = vec2(sdBox(q - vec3(0.0, 4.6, 0.0), vec3(13.6, 0.3, 0.65)), MAT_STONE);
  vec2 orb = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_ORB);

  vec2 d = opUnion(cols, beam);
  return opUnion(d, orb);
}
