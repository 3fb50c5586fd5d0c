// A round lens over u_tex0 that follows the mouse: our own example of a
// glslViewer texture bound from the command line (--texture FILE).
#ifdef GL_ES
precision mediump float;
#endif

uniform sampler2D u_tex0;
uniform vec2 u_tex0Resolution;
uniform vec2 u_resolution;
uniform vec2 u_mouse;

void main() {
  vec2 st = gl_FragCoord.xy / u_resolution.xy;
  vec2 centre = length(u_mouse) > 0.0 ? u_mouse / u_resolution.xy : vec2(0.5);
  vec2 d = (st - centre) * vec2(u_resolution.x / u_resolution.y, 1.0);
  float r = length(d);
  // Inside the rim, magnify 2x towards the centre; a dark ring marks the edge.
  vec2 uv = r < 0.3 ? centre + (st - centre) * 0.5 : st;
  vec3 colour = texture2D(u_tex0, uv).rgb;
  colour *= 1.0 - 0.6 * smoothstep(0.012, 0.0, abs(r - 0.3));
  // Texel size, for readers who want a pixelated lens: 1.0 / u_tex0Resolution.
  gl_FragColor = vec4(colour, 1.0);
}
