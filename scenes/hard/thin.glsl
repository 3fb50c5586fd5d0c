// thin.glsl (hard case 3): thin features. A plate 1e-3 thick tilted towards
// the camera (left), a torus with a thin tube (right), and two boxes with a
// hairline gap between them (top centre) through which the sky must show.
// THIN_GAP: the gap's width (world units); the plate and torus sizes are
// fixed. Keep tests/cli/stability_scenes.h in step.
#ifndef THIN_GAP
#define THIN_GAP 0.08
#endif
vec2 map(vec3 p) {
  // Plate: half thickness 5e-4, rotated 60 degrees about x (seen at 30 degrees).
  vec3 q = p - vec3(-1.6, -0.7, 0.0);
  const float c = 0.5, s = 0.8660254;
  q.yz = vec2(c * q.y - s * q.z, s * q.y + c * q.z);
  float plate = sdBox(q, vec3(0.8, 0.0005, 0.6));
  // Torus: ring radius 0.7, tube radius 0.02, tilted 60 degrees about x.
  vec3 r = p - vec3(1.6, -0.7, 0.0);
  r.yz = vec2(c * r.y - s * r.z, s * r.y + c * r.z);
  float torus = sdTorus(r, vec2(0.7, 0.02));
  // Gap: two boxes 2 deep, THIN_GAP apart at x = 0.
  float h = 0.5 * float(THIN_GAP) + 0.6;
  float gap = min(sdBox(p - vec3(-h, 1.0, 0.0), vec3(0.6, 0.5, 1.0)),
                  sdBox(p - vec3(h, 1.0, 0.0), vec3(0.6, 0.5, 1.0)));
  vec2 res = vec2(plate, MAT_PLATE);
  res = opUnion(res, vec2(torus, MAT_TORUS));
  return opUnion(res, vec2(gap, MAT_WALL));
}
