// part.json written by hand: a chamfered union of a rounded box and a
// sphere, minus a cylinder turned 90 degrees about x and scaled by 1.5.
vec2 map(vec3 p) {
  vec3 q = p - vec3(0.0, 0.6, 0.0);
  float body = opUnionChamfer(sdRoundBox(q, vec3(0.8, 0.5, 0.6), 0.1),
                              sdSphere(p - vec3(0.8, 0.9, -0.2), 0.35), 0.15);
  // R_x(90)^T q = (q.x, q.z, -q.y), then the scale.
  float hole = sdCylinder(vec3(q.x, q.z, -q.y) / 1.5, 0.3, 1.0) * 1.5;
  return vec2(opSmoothSubtraction(body, hole, 0.1), body > -hole ? MAT_BALL : MAT_FLOOR);
}
