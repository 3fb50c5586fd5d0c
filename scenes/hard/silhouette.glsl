// silhouette.glsl (hard case 2): a unit sphere alone against the sky, so the
// rays around its outline pass tangent to it.
vec2 map(vec3 p) {
  return vec2(sdSphere(p, 1.0), MAT_BALL);
}
