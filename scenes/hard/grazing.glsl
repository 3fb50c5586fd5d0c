// grazing.glsl (hard case 1): an infinite ground plane, marched as part of
// map() (not declared in [[planes]]), so primary rays near the horizon meet
// it at a near-tangent angle and sphere tracing converges slowly.
vec2 map(vec3 p) {
  return vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_GROUND);
}
