// terrain.glsl: an island of fractal noise in a still sea. The height is
//   h(x, z) = A noiseFbm((x, z) / S, 4, 0.5) + B - C max(|(x, z)| - R, 0),
// a 4-octave fbm (noise.glsl: L = 3.03 * 4 / 1.875 = 6.46 per unit of its
// argument) sloping into the sea beyond radius R. So |grad h| <= A / S *
// 6.46 + C = 1.0 / 2.4 * 6.46 + 0.3 = 2.99, and the field y - h has
// L = sqrt(1 + 2.99^2) = 3.16: terrain.toml sets lipschitz = 3.16.
// The sea is a reflective plane (terrain.toml); it also hides the slopes
// under water from the bounds check.

const float A = 1.0, S = 2.4, B = 0.1, C = 0.3, R = 3.2;

float height(vec2 xz) {
  return A * noiseFbm(xz / S + vec2(3.1, 1.7), 4, 0.5) + B - C * max(length(xz) - R, 0.0);
}

vec2 map(vec3 p) {
  return vec2(p.y - height(p.xz), p.y > 0.7 ? MAT_SNOW : MAT_ROCK);
}
