// degenerate.glsl (hard case 9): shapes with degenerate sizes, which must
// render without NaN: a zero-radius sphere (a point), a negative-radius
// sphere (never reached: its field stays >= 0.5), a torus with a zero tube,
// a capsule whose two ends coincide, and a box with a zero extent (a square).
vec2 map(vec3 p) {
  vec2 res = vec2(p.y + 1.0, MAT_GROUND);
  res = opUnion(res, vec2(sdSphere(p - vec3(-2.0, 0.0, 0.0), 0.0), MAT_ODD));
  res = opUnion(res, vec2(sdSphere(p - vec3(-1.0, 0.0, 0.0), -0.5), MAT_ODD));
  res = opUnion(res, vec2(sdTorus(p - vec3(0.0, 0.0, 0.0), vec2(0.4, 0.0)), MAT_ODD));
  res = opUnion(res, vec2(sdCapsule(p, vec3(1.0, 0.0, 0.0), vec3(1.0, 0.0, 0.0), 0.3), MAT_ODD));
  return opUnion(res, vec2(sdBox(p - vec3(2.0, 0.0, 0.0), vec3(0.3, 0.0, 0.3)), MAT_ODD));
}
