#pragma once
// Stub primitives: the scene's map file includes this again; #pragma once keeps one copy.
float sdSphere(vec3 p, float r) { return length(p) - r; }
