// trace.glsl: sphere tracing (Hart 1996) with a pixel-footprint hit
// tolerance, over-relaxation with overshoot detection (Keinert et al. 2014),
// analytic planes and bounding-volume clipping (bounds.glsl).
#pragma once
#include "aov.glsl"
#include "bounds.glsl"
#ifdef EXACT_SPHERES
#include "exact.glsl"
#endif

// What a traced ray found. `steps` is kept for the step-count AOV.
struct TraceResult {
  float t;      // distance along the ray of the hit (or where marching stopped)
  float d;      // the field value at t (< tolerance for converged hits; 0 on a plane)
  int   mat;    // material id at the hit, clamped to [0, NUM_MATERIALS-1]
  int   steps;  // map() evaluations spent
  bool  hit;    // true: t is on a surface (converged, or step budget spent near one)
  bool  capped; // true: MAX_STEPS ran out before converging or leaving the march interval (the step-cap AOV)
  bool  exact;  // true: an analytic plane was hit; n is its exact normal
  vec3  n;      // the plane's normal when exact, else 0
};

// Sphere-traces `r` from tmin to MAX_DIST. Stepping d / LIPSCHITZ is safe for
// any LIPSCHITZ-Lipschitz map(). A hit is declared when
//   d < max(HIT_EPSILON, HIT_TOLERANCE * footprint(t)),
// footprint(t) = w0 + t * spread: the ray's pixel cone (for a primary ray
// t * pixelAngle). Far hits stop early, where a sub-pixel error is invisible.
//
// Analytic planes (bounds.glsl) are intersected first; marching then ends at
// the nearest plane, and only map() is marched. With bounds, marching runs
// only over the ray's interval inside the bounding volume: a ray that misses
// it costs no step at all.
//
// Over-relaxation (OMEGA > 1): steps are omega * r. If the unbounding spheres
// of two consecutive points do not overlap (|r| + r_prev < step), the step
// may have jumped over a surface: go back to the plain step from the previous
// point (always safe) and continue with omega 1 for the rest of the ray. A
// relaxed step that would leave the interval is taken plain, so nothing near
// its end is skipped.
//
// Running out of MAX_STEPS inside the interval counts as a hit at the last t
// when the field there is below one pixel footprint: such rays graze a
// surface, and calling them misses would punch sky-coloured holes into it.
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
  res.exact = false;
  res.n = vec3(0.0);
#ifdef EXACT_SPHERES
  // The exact-intersection reference (exact.glsl): nothing is marched. A
  // sphere hit is shaded like a marched one (its normal from the field).
  float tx = float(MAX_DIST);
  int pm = 0;
  vec3 pn = vec3(0.0);
  bool onPlane = intersectPlanes(r.o, r.d, tmin, tx, pm, pn);
  int sm = intersectSpheres(r.o, r.d, tmin, tx);
  res.hit = onPlane || sm >= 0;
  res.t = res.hit ? tx : float(MAX_DIST);
  res.d = 0.0;
  res.mat = clamp(sm >= 0 ? sm : pm, 0, NUM_MATERIALS - 1);
  res.exact = res.hit && sm < 0;
  res.n = res.exact ? pn : vec3(0.0);
  return res;
#endif

  // The nearest analytic plane ends the march; the bounds clip it further.
  float tPlane = float(MAX_DIST);
  bool planeHit = false;
  int planeMat = 0;
  vec3 planeN = vec3(0.0);
#if MS_ANALYTIC_PLANES
  planeHit = intersectPlanes(r.o, r.d, tmin, tPlane, planeMat, planeN);
#endif
  float t = tmin, tEnd = tPlane;
#if MS_BOUNDS
  vec2 bi = boundsInterval(r.o, r.d, 0.0);
  t = max(t, bi.x);
  tEnd = min(tEnd, bi.y);
#endif

  vec2 h = vec2(BIG, 0.0);
  if (t <= tEnd) {
    float omega = float(OMEGA);
    float tPrev = t, rPrev = 0.0, stepLen = 0.0;
    for (int i = 0; i < MAX_STEPS; ++i) {
      h = marchMap(r.o + r.d * t);
      res.steps = i + 1;
      float rad = h.x / float(LIPSCHITZ);
      if (omega > 1.0 && stepLen > 0.0 && (abs(rad) + rPrev < stepLen || h.x < 0.0)) {
        t = tPrev + rPrev;  // overshoot: back to the plain step
        omega = 1.0;
        continue;
      }
      float tol = max(float(HIT_EPSILON), float(HIT_TOLERANCE) * (w0 + t * spread));
      if (h.x < tol) {
        res.hit = true;
        break;
      }
      stepLen = t + omega * rad > tEnd ? rad : omega * rad;
      tPrev = t;
      rPrev = rad;
      t += stepLen;
      if (t > tEnd) break;
    }
    res.capped = !res.hit && t <= tEnd;
  }
  MS_COUNT_SDF(res.steps);  // one map() per step

  // A capped ray is a hit only within a pixel footprint of a surface (a
  // grazing ray still converging); one capped far from any (a ray rising
  // slowly off a plane near the horizon) is not, or it paints ground into
  // the sky (docs/stability.md, grazing).
  bool nearSurface = res.hit || (res.capped && h.x < max(float(HIT_EPSILON), w0 + t * spread));
  if (nearSurface || !planeHit) {
    res.hit = nearSurface;  // budget spent close to a surface
    res.t = min(t, float(MAX_DIST));
    res.d = h.x;
    res.mat = clamp(int(h.y + 0.5), 0, NUM_MATERIALS - 1);
    return res;
  }
  // The march found nothing in front of the plane: an exact hit.
  res.hit = true;
  res.exact = true;
  res.t = tPlane;
  res.d = 0.0;
  res.mat = clamp(planeMat, 0, NUM_MATERIALS - 1);
  res.n = planeN;
  return res;
}
