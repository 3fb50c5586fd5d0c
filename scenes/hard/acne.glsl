// acne.glsl (hard case 7): self-intersection. A flat ground marched as part
// of map() (so shadow rays leave a marched surface), lit by a sun 3 degrees
// above the horizon; a mirror slab (material MIRROR, a box 0.05 high) on the
// right, whose reflected rays leave it at grazing angles. Nothing stands in
// the light's way: the shadow must be 1 everywhere on the ground.
vec2 map(vec3 p) {
  vec2 res = vec2(p.y, MAT_GROUND);
  return opUnion(res, vec2(sdBox(p - vec3(3.0, 0.0, 8.0), vec3(2.5, 0.05, 6.0)), MAT_MIRROR));
}
