// normals.glsl (hard case 8): a cube (sharp edges and corners, left), an
// inside corner (an L of two boxes, right), and the ground marched in map()
// out to 1e3 (a surface seen from far away).
vec2 map(vec3 p) {
  vec2 res = vec2(p.y, MAT_GROUND);
  res = opUnion(res, vec2(sdBox(p - vec3(-1.3, 0.6, 0.0), vec3(0.6)), MAT_CUBE));
  float l = min(sdBox(p - vec3(1.5, 0.15, 0.0), vec3(0.8, 0.15, 0.8)),
                sdBox(p - vec3(1.5, 0.8, 0.65), vec3(0.8, 0.8, 0.15)));
  return opUnion(res, vec2(l, MAT_CORNER));
}
