// twist.glsl (hard case 6): a box twisted about y by 2 radians per unit.
// Not a distance any more: at radius R from the axis the field's gradient
// reaches sqrt(1 + (2 R)^2). Inside [bounds] (R <= 1.3) that is <= 2.8, so
// twist.toml declares lipschitz = 3.
vec2 map(vec3 p) {
  float a = 2.0 * p.y, c = cos(a), s = sin(a);
  vec3 q = vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
  return vec2(sdBox(q, vec3(0.5, 1.0, 0.5)), MAT_SHAPE);
}
