// material.glsl: the material table lookup and the (filtered) checker pattern.
// Specialized shaders (docs/specialization.md) compile the checker only when
// a material uses it (USE_CHECKER), test for it by material id
// (MATERIAL_IS_CHECKER, from the host), and may read a folded table (the
// host's sceneMaterial(), MATERIAL_UNIFORMS 0) instead of uMaterials[].
#pragma once

#ifndef USE_CHECKER
#define USE_CHECKER 1                               // generic: any material may be a checker
#endif
#ifndef MATERIAL_IS_CHECKER
#define MATERIAL_IS_CHECKER(id) (m.pattern == 1)    // generic: read the table at run time
#endif

// Shading inputs at one surface point, after patterns are applied.
struct Surface {
  vec3  albedo;
  float ka, kd, ks, shininess;
  float f0;       // Fresnel-Schlick reflectance at normal incidence; 0 = no mirror
};

#if USE_CHECKER
// Projects a 3D point or vector onto the 2D plane across the dominant axis of
// the normal n (|n.y| largest: xz, |n.x|: zy, else xy): a 2D checker on every face.
vec2 projectDominant(vec3 v, vec3 n) {
  vec3 a = abs(n);
  if (a.y >= a.x && a.y >= a.z) return v.xz;
  if (a.x >= a.z) return v.zy;
  return v.xy;
}

// Point-sampled checker with unit cells: 0 on cells where floor(x)+floor(y)
// is even, 1 where odd. Aliases when a pixel covers many cells.
float checkerPoint(vec2 uv) {
  vec2 c = floor(uv);
  return mod(c.x + c.y, 2.0);
}

// The same checker box-filtered over a footprint spanned by duvdx, duvdy
// (Quilez, "filterable procedurals"): the closed-form integral of the
// square wave over the footprint's bounding box. Tends to the 0.5 average
// when the footprint covers many cells, which removes the horizon moire.
float checkerFiltered(vec2 uv, vec2 duvdx, vec2 duvdy) {
  vec2 w = abs(duvdx) + abs(duvdy) + 1e-3;
  // integral of the triangle wave's derivative over [uv - w/2, uv + w/2], / w
  vec2 i = 2.0 * (abs(fract((uv - 0.5 * w) * 0.5) - 0.5) -
                  abs(fract((uv + 0.5 * w) * 0.5) - 0.5)) / w;
  return saturate(0.5 - 0.5 * i.x * i.y);
}

#endif  // USE_CHECKER

// Moves the screen differentials dO + t*dD of a ray hitting at distance t
// onto the tangent plane (normal n) along the ray direction d (Igehy's
// transfer): dP = dX - d * dot(dX, n) / dot(d, n). Grazing angles are clamped
// so the footprint grows large but stays finite.
vec3 transferToSurface(vec3 dX, vec3 d, vec3 n) {
  return dX - d * safeDiv(dot(dX, n), dot(d, n), 1e-3);
}

#if MATERIAL_UNIFORMS
// Material `id` (already clamped to the table) from the uniforms. A
// specialized render shader gets the host's folded version instead.
Material sceneMaterial(int id) { return uMaterials[id]; }
#endif

// The material `id` at surface point p with normal n. dPdx, dPdy: the pixel's
// footprint on the surface (from transferToSurface). A checker material mixes
// color/color2 by the checker at (p - patternVelocity*uTime)/patternScale,
// box-filtered over the footprint when ENABLE_CHECKER_FILTER, else point-sampled.
Surface getSurface(int id, vec3 p, vec3 n, vec3 dPdx, vec3 dPdy) {
  id = clamp(id, 0, NUM_MATERIALS - 1);
  Material m = sceneMaterial(id);
  Surface s;
  s.albedo = m.color;
  s.ka = m.ka;
  s.kd = m.kd;
  s.ks = m.ks;
  s.shininess = max(m.shininess, 1e-3);
  s.f0 = saturate(m.reflectivity);
#if USE_CHECKER
  if (MATERIAL_IS_CHECKER(id)) {
    float inv = 1.0 / max(m.patternScale, 1e-6);
    vec2 uv = projectDominant(p - m.patternVelocity * uTime, n) * inv;
#if ENABLE_CHECKER_FILTER
    float c = checkerFiltered(uv, projectDominant(dPdx, n) * inv, projectDominant(dPdy, n) * inv);
#else
    float c = checkerPoint(uv);
#endif
    s.albedo = mix(m.color, m.color2, c);
  }
#endif
  return s;
}
