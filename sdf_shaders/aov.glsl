// aov.glsl: the instrumentation behind AOV outputs and debug views: cost
// counters and the debug-view colour ramps. Everything here compiles to
// nothing unless the host defines AOV_OUTPUTS 1 or DEBUG_VIEW n (see
// docs/shader-library.md, "AOVs and debug views"), so a normal render's
// code, and therefore its image, is unchanged.
#pragma once

#ifndef AOV_OUTPUTS
#define AOV_OUTPUTS 0          // 1: main.frag also writes outGeom, outMisc, outCost
#endif
#ifndef MS_COST_PRIMS
#define MS_COST_PRIMS 0        // 1: the sdf_evals output counts a scene graph's primitives instead
#endif
#ifndef DEBUG_VIEW
#define DEBUG_VIEW 0           // 0 off; 1 steps, 2 normals, 3 depth, 4 AO, 5 shadow, 6 material id
#endif

// Capturing the primary hit's shadow and AO is needed by both AOVs and debug
// views; counting work only by the AOVs.
#if AOV_OUTPUTS || DEBUG_VIEW
#define MS_CAPTURE 1
#else
#define MS_CAPTURE 0
#endif

#if AOV_OUTPUTS
// Per-sample counters (globals: map() is called from functions whose
// signatures must not change). Reset by main() for each sample.
int msSdfEvals = 0;      // every map() call: trace, normals, shadow, AO, reflections
int msShadowSteps = 0;   // shadow-ray steps over all lights and bounces
int msPrimEvals = 0;     // a scene graph's primitives evaluated, over every map() call
#define MS_COUNT_SDF(n) msSdfEvals += (n)
#define MS_COUNT_PRIMS(n) msPrimEvals += (n)
#define MS_COUNT_SHADOW_STEP() ++msShadowSteps
#else
#define MS_COUNT_SDF(n)
#define MS_COUNT_PRIMS(n)
#define MS_COUNT_SHADOW_STEP()
#endif

#if MS_CAPTURE
// Sum and count of the softShadow() results so far in this sample; main.frag
// reads them right after shading the primary hit (the first shadow rays).
float msShadowSum = 0.0;
int msShadowCount = 0;
#define MS_RECORD_SHADOW(v) msShadowSum += (v); ++msShadowCount
#else
#define MS_RECORD_SHADOW(v)
#endif

#if DEBUG_VIEW
// Steps heat map on a fixed LOG scale, so the viewer can draw a legend:
//   x = log2(steps + 1) / 8, clamped to [0,1]
// i.e. 0 steps -> 0, 3 -> 0.25, 15 -> 0.5, 63 -> 0.75, 255 (the default
// MAX_STEPS) and more -> 1. Log because the interesting range spans two
// decades (a few steps on near surfaces, hundreds on grazing rays).
float stepsHeatPosition(float steps) {
  return clamp(log2(max(steps, 0.0) + 1.0) / 8.0, 0.0, 1.0);
}

// The ramp for x in [0,1], piecewise linear through 5 stops at 0, .25, .5,
// .75, 1: dark blue, blue, green, yellow, red. Linear colour.
vec3 heatRamp(float x) {
  const vec3 c0 = vec3(0.0, 0.0, 0.25), c1 = vec3(0.0, 0.35, 1.0), c2 = vec3(0.0, 0.85, 0.2);
  const vec3 c3 = vec3(1.0, 0.9, 0.0), c4 = vec3(1.0, 0.0, 0.0);
  float s = clamp(x, 0.0, 1.0) * 4.0;
  if (s < 1.0) return mix(c0, c1, s);
  if (s < 2.0) return mix(c1, c2, s - 1.0);
  if (s < 3.0) return mix(c2, c3, s - 2.0);
  return mix(c3, c4, s - 3.0);
}

vec3 stepsHeat(float steps) { return heatRamp(stepsHeatPosition(steps)); }

// Depth as grey on a log scale: 1 at t = 0, 0 at MAX_DIST:
// 1 - log2(1 + t) / log2(1 + MAX_DIST). Near geometry stays distinguishable.
float depthShade(float t) {
  return 1.0 - clamp(log2(1.0 + max(t, 0.0)) / log2(1.0 + float(MAX_DIST)), 0.0, 1.0);
}

// A distinct colour per material id: hues spaced by the golden ratio, so
// neighbouring ids never look alike.
vec3 materialColor(int id) {
  float h = fract(0.1 + 0.618034 * float(id));
  vec3 rgb = clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
  return 0.9 * mix(vec3(1.0), rgb, 0.75);
}
#endif
