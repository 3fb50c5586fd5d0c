// Stub operators.
vec2 opU(vec2 a, vec2 b) { return a.x < b.x ? a : b; }
