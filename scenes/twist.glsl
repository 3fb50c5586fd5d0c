// twist.glsl: three deformed shapes, each with the Lipschitz factor of its
// deformation (domain.glsl, combinators.glsl):
//   a twisted column: domTwist, k = 1.4 rad per unit, |p.xz| <= 0.42 in its
//     cylinder: L = (a + sqrt(a^2 + 4)) / 2 with a = 0.588: 1.34;
//   a bent bar: domBend, k = 0.9, |p.xy| <= 0.82: L = 1 + 0.9 * 0.82 = 1.74;
//   a displaced ball: opDisplace by 0.06 noiseGradient(4 p):
//     L = 1 + 0.06 * 4 * 3.26 = 1.79.
// Those factors hold inside each shape's bounding volume; outside it the
// field is the distance to that volume plus the gap the shape keeps from
// the volume's surface, which never overestimates the distance to the
// shape. So the whole field never exceeds 1.79 x the distance to its
// surface: twist.toml sets lipschitz = 1.79.

vec2 map(vec3 p) {
  // Each shape: outside its bounding volume the distance to the volume plus
  // the gap (no deformation evaluated there), inside the deformed field.
  vec3 a = p - vec3(-1.5, 0.92, 0.0);
  float column = sdCylinder(a, 0.42, 0.93);             // the column keeps 0.03 inside
  column = column > 0.0 ? column + 0.03 : sdRoundBox(domTwist(a, 1.4), vec3(0.28, 0.9, 0.28), 0.03);

  vec3 b = p - vec3(0.1, 0.45, 0.3);
  float bar = sdCylinder(b.xzy, 0.82, 0.2);              // the bar keeps 0.01 inside
  bar = bar > 0.0 ? bar + 0.01 : sdRoundBox(domBend(b, 0.9), vec3(0.8, 0.12, 0.18), 0.04);

  vec3 c = p - vec3(1.45, 0.62, -0.2);
  float ball = sdSphere(c, 0.58);                        // the ball keeps 0.02 inside
  ball = ball > 0.0 ? ball + 0.02 : opDisplace(sdSphere(c, 0.5), 0.06 * noiseGradient(c * 4.0));

  vec2 d = opUnion(vec2(column, MAT_COPPER), vec2(bar, MAT_ENAMEL));
  return opUnion(d, vec2(ball, MAT_CLAY));
}
