// Buffer A of trail.glsl: a dot on a Lissajous path, over its own last
// frame ("self") faded a little each frame. Hold D to hide the dot.
#iChannel0 "self"
#iChannel0::WrapMode "Clamp"
#iKeyboard
#iUniform float fade = 0.92 in { 0.5, 1.0 }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec2 dot = 0.5 + 0.35 * vec2(sin(iTime * 1.3), sin(iTime * 2.1));
    float d = length((uv - dot) * vec2(iResolution.x / iResolution.y, 1.0));
    float spot = isKeyDown(Key_D) ? 0.0 : smoothstep(0.05, 0.0, d);
    vec3 prev = texture(iChannel0, uv).rgb;
    fragColor = vec4(max(prev * fade, vec3(spot)), 1.0);
}
