// city.glsl: a city of 9 x 9 blocks by limited repetition (domRepeatLimited)
// with a tower on every block whose height and setback vary by block
// (domRepeatCell and a hash). Every copy of a repeated shape must fit its
// cell, and a copy that differs from its neighbours breaks the repetition
// rule (a taller neighbour can be nearer than the cell's own tower), so the
// field is also capped by the distance out of the cell plus the street
// between towers: no neighbour can be nearer than that. The minimum of two
// 1-Lipschitz bounds: lipschitz stays 1.

const vec2 kCell = vec2(2.0);       // block pitch
const vec2 kLimit = vec2(4.0);      // blocks -4..4 each way
const float kStreet = 0.35;         // half the street: a tower's footprint stays inside cell +- (1 - kStreet)

// A hash of the block in [0, 1): integer arithmetic only, so every CPU and
// GPU gets the same city (sin-based hashes differ between instruction sets).
float blockHash(vec2 c) {
  uvec2 v = uvec2(ivec2(c) + 64);
  uint h = v.x * 1664525u + v.y * 1013904223u;
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  h ^= h >> 16u;
  return float(h >> 8u) * (1.0 / 16777216.0);
}

vec2 tower(vec3 q, vec2 cell) {
  float h = 0.6 + 2.6 * blockHash(cell) * (1.0 - 0.09 * length(cell));   // taller towards the centre
  float w = 1.0 - kStreet - 0.15 * blockHash(cell + 23.0);
  float body = sdBox(q - vec3(0.0, h, 0.0), vec3(w, h, w));
  // A setback crown: a narrower box on top.
  float crown = sdBox(q - vec3(0.0, 2.0 * h + 0.25, 0.0), vec3(0.6 * w, 0.25, 0.6 * w));
  float d = opUnion(body, crown);
  return vec2(d, blockHash(cell + 11.0) > 0.5 ? MAT_GLASS : MAT_CONCRETE);
}

vec2 map(vec3 p) {
  vec2 cell = domRepeatCell(p.xz, kCell, kLimit);
  vec3 q = vec3(domRepeatLimited(p.xz, kCell, kLimit), p.y).xzy;
  vec2 t = tower(q, cell);
  // Out of this cell's tower footprint to the next cell's: never farther
  // than the cell wall plus the street.
  vec2 inner = kCell * 0.5 - abs(q.xz);
  float leave = max(min(inner.x, inner.y), 0.0) + kStreet;
  return vec2(min(t.x, leave), t.y);
}
