// squash.glsl (hard case 6): non-uniform scale done the wrong way. A unit
// sphere scaled by s = (2, 0.5, 1) and multiplied back by the largest factor
// (2) overestimates the distance up to max(s)/min(s) = 4 times near the
// flat sides (the safe form multiplies by min(s) instead); squash.toml
// declares lipschitz = 4.
vec2 map(vec3 p) {
  const vec3 s = vec3(2.0, 0.5, 1.0);
  return vec2(sdSphere(p / s, 1.0) * 2.0, MAT_SHAPE);
}
