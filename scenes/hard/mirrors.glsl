// mirrors.glsl (hard case 10): a sphere between two parallel mirrors (the
// planes x = -2 and x = 2, declared in mirrors.toml), so a ray bounces
// between them as often as [quality] bounces allows.
vec2 map(vec3 p) {
  return vec2(sdSphere(p - vec3(0.0, 0.0, 2.0), 0.6), MAT_BALL);
}
