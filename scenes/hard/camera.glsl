// camera.glsl (hard case 5): a marched ground plane (y < 0 is solid) and a
// box (solid for |x|, |z| < 2, 0 < y < 2) for cameras placed inside a solid
// or exactly on a surface (inside.toml, on_surface.toml).
vec2 map(vec3 p) {
  vec2 res = vec2(p.y, MAT_GROUND);
  return opUnion(res, vec2(sdBox(p - vec3(0.0, 1.0, 6.0), vec3(2.0, 1.0, 2.0)), MAT_BOX));
}
