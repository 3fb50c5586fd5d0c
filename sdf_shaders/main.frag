// main.frag: the per-sample pipeline. Primary ray -> trace -> shade ->
// reflections (a loop with a throughput, no recursion) -> linear radiance.
// The root has already included prelude, primitives, operators and the
// scene's map(); this file pulls in the rest of the library.
#pragma once
#include "sky.glsl"
#include "camera.glsl"
#include "trace.glsl"
#include "normals.glsl"
#include "shadow.glsl"
#include "ao.glsl"
#include "material.glsl"
#include "lighting.glsl"

#if ENABLE_REFLECTIONS && MAX_BOUNCES > 0
#define MS_SEGMENTS (MAX_BOUNCES + 1)   // primary ray + one per bounce
#else
#define MS_SEGMENTS 1
#endif

// Fresnel-Schlick reflectance for F0 and the cosine between normal and viewer.
float fresnelSchlick(float f0, float cosTheta) {
  float m = 1.0 - saturate(cosTheta);
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

// How far secondary rays (shadow, reflection) start off a surface whose pixel
// footprint is `fp` wide: beyond the hit tolerance (so the ray does not
// re-hit the surface it left), still sub-pixel (so shadows do not float).
float surfaceOffset(float fp) {
  return max(10.0 * float(HIT_EPSILON), (float(HIT_TOLERANCE) + 1.0) * fp);
}

// Radiance of one sample: rays through the scene, each hit adding its local
// Blinn-Phong shading weighted by the throughput, each mirror bounce scaling
// the throughput by Fresnel F (so local shading gets 1 - F). Hits fade into
// the sky near MAX_DIST. Stops on a miss, once throughput < 1e-3, or after
// MAX_BOUNCES (the last hit's mirror term then reflects the sky only).
vec3 renderSample(vec2 pix, out int primarySteps) {
  Ray ray = cameraRay(pix);
  vec3 radiance = vec3(0.0);
  vec3 throughput = vec3(1.0);
  primarySteps = 0;
  for (int seg = 0; seg < MS_SEGMENTS; ++seg) {
    TraceResult tr = trace(ray, 0.0);
    if (seg == 0) primarySteps = tr.steps;
    if (!tr.hit) {
      radiance += throughput * skyColor(ray.d);
      break;
    }
    float fade = distanceFade(tr.t);
    radiance += throughput * fade * skyColor(ray.d);
    throughput *= 1.0 - fade;
    if (fade > 0.999) break;   // lost in the haze: skip the shading

    float fp = rayFootprint(ray, tr.t);
    vec3 p = ray.o + ray.d * tr.t;
    vec3 n = calcNormal(p, normalEpsilon(p, fp), -ray.d);
    // Snap onto the surface: converged hits stop up to a tolerance short of
    // it, and AO and the checker want the surface itself.
    p -= n * clamp(tr.d, 0.0, fp);
    // Seen from behind only at silhouettes (tolerance hits): tilt the normal
    // until it faces the viewer so lighting and reflection stay sane.
    float nd = dot(n, ray.d);
    if (nd > -1e-3) n = safeNormalize(n - ray.d * (nd + 1e-3), -ray.d);

    vec3 dPdx = transferToSurface(ray.dOdx + tr.t * ray.dDdx, ray.d, n);
    vec3 dPdy = transferToSurface(ray.dOdy + tr.t * ray.dDdy, ray.d, n);
    Surface s = getSurface(tr.mat, p, n, dPdx, dPdy);
    float offset = surfaceOffset(fp);
    vec3 local = shadeBlinnPhong(s, p, n, -ray.d, ambientOcclusion(p, n), offset);

#if MS_SEGMENTS > 1
    float F = s.f0 > 0.0 ? fresnelSchlick(s.f0, dot(n, -ray.d)) : 0.0;
    if (seg == MS_SEGMENTS - 1) {
      // No bounce left: the sky stands in for what the mirror would show, so
      // a truncated path does not turn grey or black (e.g. at silhouettes).
      radiance += throughput * mix(local, skyColor(reflect(ray.d, n)), F);
      break;
    }
    radiance += throughput * (1.0 - F) * local;
    throughput *= F;
    if (maxComp(throughput) < 1e-3) break;
    // Reflect the ray and its differentials (flat-mirror transfer, Igehy;
    // surface curvature ignored).
    ray.o = p + n * offset;
    ray.d = reflect(ray.d, n);
    ray.dOdx = dPdx;
    ray.dOdy = dPdy;
    ray.dDdx = reflect(ray.dDdx, n);
    ray.dDdy = reflect(ray.dDdy, n);
#else
    radiance += throughput * local;
#endif
  }
  return radiance;
}

void main() {
  int primarySteps;  // kept for the step-count AOV
  vec3 c = renderSample(floor(gl_FragCoord.xy) + uJitter, primarySteps);
  // Last line of defence: the pipeline guards its divisions, but a user map()
  // may not; a NaN would poison the whole accumulation buffer.
  if (notFinite(c)) c = vec3(0.0);
  outColor = vec4(max(c, vec3(0.0)), 1.0);
}
