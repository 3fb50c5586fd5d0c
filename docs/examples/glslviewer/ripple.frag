// A glslViewer-style shader of our own: rings from the centre, a time
// pulse, and a double buffer that keeps a fading trail of them.
#ifdef GL_ES
precision mediump float;
#endif

uniform vec2 u_resolution;
uniform float u_time;
uniform sampler2D u_doubleBuffer0;
varying vec2 v_texcoord;

void main() {
    vec2 st = gl_FragCoord.xy / u_resolution.xy;
    float d = length(st - 0.5);
    float ring = smoothstep(0.02, 0.0, abs(fract(d * 6.0 - u_time) - 0.5) - 0.1);
#ifdef DOUBLE_BUFFER_0
    vec3 prev = texture2D(u_doubleBuffer0, v_texcoord).rgb;
    gl_FragColor = vec4(max(prev * 0.9, vec3(ring * st.x, ring * 0.5, ring * st.y)), 1.0);
#else
    gl_FragColor = vec4(texture2D(u_doubleBuffer0, v_texcoord).rgb, 1.0);
#endif
}
