// Stub post pass.
#if TONEMAP < 0 || TONEMAP > 2
#error TONEMAP out of range
#endif
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(float(TONEMAP), float(ENCODE_SRGB), 0.0, 1.0); }
