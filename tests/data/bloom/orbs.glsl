// orbs.glsl: docs/post.md's demo. The seed scene's ball with three small
// glowing orbs around it (material "glow": a large ambient, ~5 in linear
// radiance, so [post.bloom] threshold 1 picks them out).
vec2 map(vec3 p) {
  vec2 d = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_BALL);
  float o = min(sdSphere(p - vec3(-1.9, 0.35, -0.6), 0.18), sdSphere(p - vec3(1.7, 1.9, -0.2), 0.12));
  o = min(o, sdSphere(p - vec3(0.6, 0.25, -1.3), 0.1));
  return d.x < o ? d : vec2(o, MAT_GLOW);
}
