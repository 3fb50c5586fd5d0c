// Our own sky for scenes/env: an equirectangular HDR map (row 0 = up).
void mainImage(out vec4 o, in vec2 f) {
  vec2 uv = f / iResolution.xy;
  float theta = (1.0 - uv.y) * 3.14159265;    // render's row 0 is the image's top
  float phi = (uv.x - 0.5) * 6.2831853;
  vec3 d = vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
  vec3 sky = mix(vec3(0.9, 0.95, 1.1), vec3(0.15, 0.35, 0.9), pow(max(d.y, 0.0), 0.5));
  vec3 ground = mix(vec3(0.35, 0.3, 0.25), vec3(0.12, 0.1, 0.08), pow(max(-d.y, 0.0), 0.5));
  vec3 c = d.y > 0.0 ? sky : ground;
  vec3 sun = normalize(vec3(0.6, 0.45, 0.65));
  c += vec3(60.0, 52.0, 40.0) * pow(max(dot(d, sun), 0.0), 900.0);   // a small bright sun
  c += vec3(1.5, 0.9, 0.5) * pow(max(dot(d, sun), 0.0), 12.0) * 0.4;  // its glow
  o = vec4(c, 1.0);
}
