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
