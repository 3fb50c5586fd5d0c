// Not a Shadertoy shader: it has its own main.
out vec4 c;
void main() { c = vec4(1.0); }
