// common.glsl: constants and pure math helpers. No uniforms and no host
// defines, so primitives.glsl and operators.glsl (which use these) can be
// included by plain Shadertoy shaders too.
#pragma once

const float PI  = 3.14159265358979;
const float TAU = 6.28318530717959;
const float BIG = 1e20;         // "no previous step" / "infinitely far", still finite

// Clamp to [0,1].
float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec3  saturate(vec3 x)  { return clamp(x, vec3(0.0), vec3(1.0)); }

// Largest component.
float maxComp(vec3 v) { return max(v.x, max(v.y, v.z)); }

// normalize() that returns `fallback` instead of NaN for zero (or denormal) vectors.
vec3 safeNormalize(vec3 v, vec3 fallback) {
  float l2 = dot(v, v);
  return l2 > 1e-30 ? v * inversesqrt(l2) : fallback;
}
vec3 safeNormalize(vec3 v) { return safeNormalize(v, vec3(0.0, 1.0, 0.0)); }

// a / b with |b| kept >= eps (sign preserved, b = 0 counts as positive).
float safeDiv(float a, float b, float eps) {
  return a / (b < 0.0 ? min(b, -eps) : max(b, eps));
}

// Component of v perpendicular to the unit vector d.
vec3 perpTo(vec3 v, vec3 d) { return v - d * dot(v, d); }

// True when any component is NaN or +-Inf (x != x catches NaN; Inf by magnitude).
bool notFinite(vec3 v) {
  return any(notEqual(v, v)) || maxComp(abs(v)) > 3e38;
}

// ---- helpers of the distance functions (ms: internal, never guarded) ----

// Squared length.
float msDot2(vec2 v) { return dot(v, v); }
float msDot2(vec3 v) { return dot(v, v); }

// z of the 3D cross product of (a, 0) and (b, 0): > 0 when b lies counter-clockwise of a.
float msCross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Signed distance of a box from q = abs(p) - halfExtents: the outside part by
// Euclid, the inside part by the nearest face. Exact.
float msBoxQ(vec2 q) { return length(max(q, 0.0)) + min(max(q.x, q.y), 0.0); }
float msBoxQ(vec3 q) { return length(max(q, 0.0)) + min(maxComp(q), 0.0); }

// Squared distance from p to the segment a-b (a == b: to the point).
float msSegment2(vec2 p, vec2 a, vec2 b) {
  vec2 pa = p - a, ba = b - a;
  return msDot2(pa - ba * clamp(dot(pa, ba) / max(dot(ba, ba), 1e-20), 0.0, 1.0));
}
float msSegment2(vec3 p, vec3 a, vec3 b) {
  vec3 pa = p - a, ba = b - a;
  return msDot2(pa - ba * clamp(dot(pa, ba) / max(dot(ba, ba), 1e-20), 0.0, 1.0));
}
