// normals.glsl: surface normals from the distance field's gradient.
#pragma once
#include "aov.glsl"
#include "bounds.glsl"

#ifndef NORMAL_EPS_SCALE
#define NORMAL_EPS_SCALE 0.5   // normal epsilon per pixel footprint (0: the fixed NORMAL_EPS_MIN)
#endif

// Normal epsilon for a hit whose pixel footprint is `footprint` wide:
// NORMAL_EPS_SCALE (half) a footprint (matches the hit tolerance, so the 4
// taps straddle what the tracer resolved), never below NORMAL_EPS_MIN nor the
// float precision at p.
float normalEpsilon(vec3 p, float footprint) {
  return max(max(float(NORMAL_EPS_SCALE) * footprint, float(NORMAL_EPS_MIN)), 4e-7 * maxComp(abs(p)));
}

// Tetrahedron-technique gradient (4 taps instead of 6; Quilez) of the whole
// scene's field (sceneMap: map() and any declared planes), normalized.
// A zero gradient (medial points, flat-topped fields) gives `fallback`, never NaN.
// The loop is not unrolled on purpose (the bound depends on uResolution, at
// least 1, so min() is 0): map() is inlined once, not four times, which keeps
// compile times down for large scenes. Not uFrame: a program that reads it
// changes every frame, and the viewer would never accumulate a still scene.
vec3 calcNormal(vec3 p, float eps, vec3 fallback) {
  vec3 n = vec3(0.0);
  for (int i = min(int(uResolution.x), 0); i < 4; ++i) {
    // (+,-,-), (-,-,+), (-,+,-), (+,+,+): the tetrahedron's vertices
    vec3 e = 2.0 * vec3(((i + 3) >> 1) & 1, (i >> 1) & 1, i & 1) - 1.0;
    n += e * sceneMap(p + e * eps).x;
  }
  MS_COUNT_SDF(4);
  return safeNormalize(n, fallback);
}
