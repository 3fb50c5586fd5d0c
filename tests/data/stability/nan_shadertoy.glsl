// A Shadertoy shader whose left 8 columns are NaN (0/0 at run time: iTime is
// 0) and the rest grey: the NaN/Inf guard of render must count 8 * height pixels.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float z = iTime;
  fragColor = fragCoord.x < 8.0 ? vec4(vec3(z / z), 1.0) : vec4(0.5, 0.5, 0.5, 1.0);
}
