// bend.glsl (hard case 6): a long bar bent in the xy plane, 0.8 radians per
// unit of x. Gradient up to sqrt(1 + (0.8 R)^2) <= 1.6 inside [bounds]
// (R <= 1.6); bend.toml declares lipschitz = 2.
vec2 map(vec3 p) {
  float a = 0.8 * p.x, c = cos(a), s = sin(a);
  vec3 q = vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
  return vec2(sdBox(q, vec3(1.4, 0.15, 0.3)), MAT_SHAPE);
}
