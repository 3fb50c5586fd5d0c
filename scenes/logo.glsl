// logo.glsl: a 2D logo made solid. The letters M and S and a star are 2D
// distances (primitives2d.glsl: strokes of segments, two arcs, a star),
// extruded through opExtrude and rounded with opRound; they stand on a
// pedestal whose profile (a 2D trapezoid and rounded box) is revolved with
// domRevolve. Extrusion and revolution keep an exact 2D distance exact, the
// unions keep a bound: lipschitz stays 1.

float letterM(vec2 q) {
  float d = ud2Segment(q, vec2(-1.0, -0.5), vec2(-1.0, 0.5));
  d = min(d, ud2Segment(q, vec2(-1.0, 0.5), vec2(-0.7, 0.0)));
  d = min(d, ud2Segment(q, vec2(-0.7, 0.0), vec2(-0.4, 0.5)));
  d = min(d, ud2Segment(q, vec2(-0.4, 0.5), vec2(-0.4, -0.5)));
  return d - 0.08;
}

// S: the upper bowl spans 20..270 degrees of its circle, the lower -160..90:
// each arc (centred on +y in sd2Arc) turned to its middle angle.
float letterS(vec2 q) {
  const vec2 sc = vec2(sin(2.18), cos(2.18));
  float top = sd2Arc(domRotate(q - vec2(0.2, 0.25), 0.96), sc, 0.25, 0.08);
  float bottom = sd2Arc(domRotate(q - vec2(0.2, -0.25), -2.18), sc, 0.25, 0.08);
  return min(top, bottom);
}

vec2 map(vec3 p) {
  // The logo's plane faces the camera (at -z), whose right is -x: mirror x
  // so it reads left to right (a mirror keeps the distance exact).
  vec3 l = p - vec3(0.0, 1.12, 0.0);
  vec2 q = vec2(-l.x, l.y);
  float logo2d = min(letterM(q), letterS(q));
  float logo = opRound(opExtrude(logo2d + 0.02, l.z, 0.1), 0.02);
  float star2d = sd2Star(domRotate(q - vec2(0.8, 0.35), 1.5708), 0.2, 0.09, 5.0);   // a tip up
  float star = opRound(opExtrude(star2d + 0.02, l.z, 0.06), 0.02);
  // The pedestal: a trapezoid profile and a rim, revolved about y.
  vec2 r = domRevolve(p, 0.0);
  float pedestal = sd2Trapezoid(r - vec2(0.0, 0.3), 1.45, 1.2, 0.3);
  pedestal = min(pedestal, sd2RoundBox(domRevolve(p - vec3(0.0, 0.62, 0.0), 1.0), vec2(0.12, 0.03), 0.02));
  vec2 d = opUnion(vec2(logo, MAT_LETTERS), vec2(star, MAT_STAR));
  return opUnion(d, vec2(pedestal, MAT_BASE));
}
