// A small animated Shadertoy shader for docs/testing.md's frame-range case:
// rings that drift with iTime over a gradient.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  float rings = 0.5 + 0.5 * cos(12.0 * length(uv) - 3.0 * iTime);
  vec3 base = mix(vec3(0.10, 0.20, 0.45), vec3(0.95, 0.60, 0.20), fragCoord.x / iResolution.x);
  fragColor = vec4(base * (0.35 + 0.65 * rings), 1.0);
}
