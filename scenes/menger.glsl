// menger.glsl: a Menger sponge by its distance estimator. The sponge is a
// cube with a cross of square holes bored through it at every scale: at
// level i, space repeated in cells of size 2 / 3^i, the three bars of half
// width 1 / 3^(i+1) through each cell's centre. Each level's field is a
// 1-Lipschitz bound scaled back to world units (f(s p) / s), and carving is
// a max, so the whole stays a 1-Lipschitz bound: lipschitz stays 1.
// The pedestal and the floor plane (menger.toml) are exact.

const int kLevels = 3;   // the fourth's holes are under a pixel at the golden's size (160 x 90)

float menger(vec3 p) {
  float d = sdBox(p, vec3(1.0));
  float s = 1.0;
  for (int i = 0; i < kLevels; ++i) {
    vec3 q = abs(domRepeat(p * s, vec3(2.0)));          // the cell, folded to one octant
    // Inside the cross the distance to its walls (max norm in the plane
    // across each bar); carve it out.
    float cross = min(min(max(q.x, q.y), max(q.y, q.z)), max(q.z, q.x)) - 1.0 / 3.0;
    d = max(d, -cross / s);
    s *= 3.0;
  }
  return d;
}

vec2 map(vec3 p) {
  vec3 q = p - vec3(0.0, 1.25, 0.0);
  q.xz = domRotate(q.xz, 0.6);
  vec2 sponge = vec2(menger(q), MAT_SPONGE);
  vec2 plinth = vec2(sdRoundBox(p - vec3(0.0, 0.1, 0.0), vec3(1.5, 0.1, 1.5), 0.03), MAT_STONE);
  return opUnion(sponge, plinth);
}
