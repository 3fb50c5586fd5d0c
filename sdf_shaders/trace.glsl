// trace.glsl: sphere tracing (Hart 1996) with a pixel-footprint hit tolerance.
#pragma once
#include "aov.glsl"

// What a traced ray found. `steps` is kept for the step-count AOV.
struct TraceResult {
  float t;      // distance along the ray of the hit (or where marching stopped)
  float d;      // the field value at t (< tolerance for converged hits)
  int   mat;    // material id at the hit, clamped to [0, NUM_MATERIALS-1]
  int   steps;  // map() evaluations spent
  bool  hit;    // true: t is on a surface (converged, or step budget spent near one)
  bool  capped; // true: MAX_STEPS ran out before converging or passing MAX_DIST (the step-cap AOV)
};

// Sphere-traces `r` from tmin to MAX_DIST, stepping d / LIPSCHITZ, which is
// safe for any LIPSCHITZ-Lipschitz map(). A hit is declared when
//   d < max(HIT_EPSILON, HIT_TOLERANCE * footprint(t)),
// footprint(t) = w0 + t * spread: the ray's pixel cone (for a primary ray
// t * pixelAngle). Far hits stop early, where a sub-pixel error is invisible.
// Running out of MAX_STEPS before MAX_DIST counts as a hit at the last t:
// such rays graze a surface (e.g. the plane near the horizon), and calling
// them misses would punch sky-coloured holes into it.
TraceResult trace(Ray r, float tmin) {
  float w0 = max(length(perpTo(r.dOdx, r.d)), length(perpTo(r.dOdy, r.d)));
  float spread = max(length(r.dDdx), length(r.dDdy));
  TraceResult res;
  res.t = tmin;
  res.d = BIG;
  res.mat = 0;
  res.steps = 0;
  res.hit = false;
  res.capped = false;
  float t = tmin;
  vec2 h = vec2(BIG, 0.0);
  for (int i = 0; i < MAX_STEPS; ++i) {
    h = map(r.o + r.d * t);
    res.steps = i + 1;
    float tol = max(float(HIT_EPSILON), float(HIT_TOLERANCE) * (w0 + t * spread));
    if (h.x < tol) {
      res.hit = true;
      break;
    }
    t += h.x / float(LIPSCHITZ);
    if (t > float(MAX_DIST)) break;
  }
  res.capped = !res.hit && t <= float(MAX_DIST);
  res.hit = res.hit || res.capped;  // budget spent close to a surface
  MS_COUNT_SDF(res.steps);          // one map() per step
  res.t = min(t, float(MAX_DIST));
  res.d = h.x;
  res.mat = clamp(int(h.y + 0.5), 0, NUM_MATERIALS - 1);
  return res;
}
