// offset.glsl (hard case 4b): a unit sphere resting on a box, 1e5 from the
// origin along x. float32 resolves about 0.008 there: map() sees p rounded
// to that grid, which no tracer change can undo (docs/stability.md).
#ifndef OFFSET_X
#define OFFSET_X 1e5
#endif
vec2 map(vec3 p) {
  p.x -= float(OFFSET_X);
  vec2 res = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_BALL);
  return opUnion(res, vec2(sdBox(p - vec3(0.0, -0.25, 0.0), vec3(2.0, 0.25, 2.0)), MAT_BLOCK));
}
