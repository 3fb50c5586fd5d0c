// organic.glsl: smooth blends (operators.glsl's polynomial smooth union,
// subtraction and intersection) of ellipsoids, round cones and capsules: a
// squat creature with a ridged back, four legs, two eyes in sockets. Every
// input is a 1-Lipschitz bound and the smooth blends keep that: lipschitz
// stays 1.

vec2 map(vec3 p) {
  vec3 q = vec3(abs(p.x), p.y, p.z);                     // left-right symmetric
  float body = sdEllipsoid(p - vec3(0.0, 0.95, 0.0), vec3(0.75, 0.5, 0.95));
  float head = sdEllipsoid(p - vec3(0.0, 1.25, -0.85), vec3(0.42, 0.38, 0.4));
  float d = opSmoothUnion(body, head, 0.35);
  // Four legs, each a round cone from the hip down to a foot.
  vec3 l = vec3(q.x - 0.45, p.y, abs(p.z) - 0.5);
  float leg = sdRoundCone(l - vec3(0.0, 0.12, 0.0), 0.12, 0.2, 0.6);
  d = opSmoothUnion(d, leg, 0.25);
  // A ridge of spines along the back, blended in.
  float spines = BIG;
  for (int i = 0; i < 5; ++i) {
    float z = -0.45 + 0.25 * float(i);
    spines = min(spines, sdCapsule(p, vec3(0.0, 1.35, z), vec3(0.0, 1.62 - 0.04 * abs(float(i) - 2.0), z + 0.12), 0.06));
  }
  d = opSmoothUnion(d, spines, 0.12);
  // Eye sockets carved smoothly, then the eyes.
  vec3 e = q - vec3(0.2, 1.38, -1.12);
  d = opSmoothSubtraction(d, sdSphere(e, 0.13), 0.06);
  vec2 res = vec2(d, MAT_SKIN);
  res = opUnion(res, vec2(sdSphere(e - vec3(0.0, 0.0, 0.03), 0.085), MAT_EYE));
  // A pebble beside it: a sphere and a box smoothly intersected.
  vec3 s = p - vec3(1.3, 0.18, -0.6);
  float pebble = opSmoothIntersection(sdSphere(s, 0.28), sdBox(s, vec3(0.3, 0.18, 0.24)), 0.08);
  return opUnion(res, vec2(pebble, MAT_PEBBLE));
}
