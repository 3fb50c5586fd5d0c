// A VS Code Shader Toy file of our own: the image shows a buffer that
// draws a moving dot and keeps a fading trail of it, tinted by a slider.
#iChannel0 "file://trail_buffer.glsl"
#iUniform color3 tint = color3(1.0, 0.8, 0.5)

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 trail = texture(iChannel0, uv).rgb;
    fragColor = vec4(trail * tint + 0.05 * vec3(uv, 1.0), 1.0);
}
