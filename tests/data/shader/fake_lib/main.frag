// Stub pipeline.
void main() {
  vec2 h = map(vec3(0.0, 1.0, 0.0) * kMaxDist * kHitEps);
  outColor = vec4(h, float(kMaxSteps), 1.0);
}
