// lighting.glsl: Blinn-Phong direct lighting over the scene's lights.
// Generic shader: a loop over uLights[] that tests each light's kind at run
// time. Specialized shader (SPECIALIZED 1, docs/specialization.md): the host
// gives the number of each kind, each light's kind as a constant
// (LIGHT_IS_POINT), and in a render shader its values as constant tables
// (LIGHT_POS, LIGHT_COLOR, LIGHT_SIZE, LIGHT_ATTEN); one light has no loop.
#pragma once

#ifndef NUM_POINT_LIGHTS             // generic: both kinds may occur
#define NUM_POINT_LIGHTS NUM_LIGHTS
#endif
#ifndef NUM_DIRECTIONAL_LIGHTS
#define NUM_DIRECTIONAL_LIGHTS NUM_LIGHTS
#endif
#ifndef LIGHT_IS_POINT                 // generic: the kind is read at run time
#define LIGHT_IS_POINT(i) (uLights[i].pos.w > 0.5)
#endif
#ifndef LIGHT_POS                      // the light's values: its uniforms unless folded
#define LIGHT_POS(i)   uLights[i].pos.xyz
#define LIGHT_COLOR(i) uLights[i].color
#define LIGHT_SIZE(i)  uLights[i].size
#define LIGHT_ATTEN(i) uLights[i].atten
#endif

// Where a light comes from as seen from p: unit direction towards it (l),
// the distance a shadow ray may travel (tmax), the distance attenuation, and
// the penumbra sharpness k = 1/tan(angular radius of the light seen from p).
// Point: angular radius atan(size/dist), so k = dist/size; the shadow ray
// stops at the light's surface. Directional: angular radius = size; the
// shadow ray runs to MAX_DIST. Zero sizes and zero distances stay finite.
#if NUM_POINT_LIGHTS > 0
void pointLightAt(vec3 pos, float size, vec3 attenCoef, vec3 p,
                  out vec3 l, out float tmax, out float atten, out float k) {
  vec3 v = pos - p;
  float dist = length(v);
  l = safeNormalize(v, vec3(0.0, 1.0, 0.0));
  tmax = max(dist - size, 0.0);
  atten = 1.0 / max(attenCoef.x + attenCoef.y * dist + attenCoef.z * dist * dist, 1e-6);
  k = shadowSharpness(size / max(dist, 1e-6));
}
#endif

#if NUM_DIRECTIONAL_LIGHTS > 0
// `dir`: the direction the light travels; `size`: its angular radius (radians).
void directionalLightAt(vec3 dir, float size, out vec3 l, out float tmax, out float atten, out float k) {
  l = -safeNormalize(dir, vec3(0.0, -1.0, 0.0));
  tmax = float(MAX_DIST);
  atten = 1.0;
  k = shadowSharpness(tan(clamp(size, 0.0, 1.4)));
}
#endif

// One light's term: Ip*(Kd*albedo*(N.L) + Ks*(H.N)^s) * atten * shadow, with
// H = normalize(L + V). Nothing (and no shadow ray) where N.L <= 0. Shadow
// rays start at p + n*offset (offset: see main.frag).
vec3 lightTerm(Surface s, vec3 p, vec3 n, vec3 v, float offset, vec3 color,
               vec3 l, float tmax, float atten, float k) {
  float ndl = dot(n, l);
  if (ndl <= 0.0) return vec3(0.0);
  vec3 h = safeNormalize(l + v, n);
  float spec = s.ks * pow(max(dot(h, n), 0.0), s.shininess);
  float sh = softShadow(p + n * offset, l, tmax, k);
  return color * (s.kd * s.albedo * ndl + spec) * (atten * sh);
}

// Light i's term. Its kind and values come through the LIGHT_* macros: the
// uniforms by default, the host's folded tables in a specialized render
// shader. With one kind only, the other kind's code is not compiled.
#if NUM_LIGHTS > 0
vec3 sceneLight(int i, Surface s, vec3 p, vec3 n, vec3 v, float offset) {
  vec3 l;
  float tmax, atten, k;
#if NUM_DIRECTIONAL_LIGHTS == 0
  pointLightAt(LIGHT_POS(i), LIGHT_SIZE(i), LIGHT_ATTEN(i), p, l, tmax, atten, k);
#elif NUM_POINT_LIGHTS == 0
  directionalLightAt(LIGHT_POS(i), LIGHT_SIZE(i), l, tmax, atten, k);
#else
  if (LIGHT_IS_POINT(i))
    pointLightAt(LIGHT_POS(i), LIGHT_SIZE(i), LIGHT_ATTEN(i), p, l, tmax, atten, k);
  else
    directionalLightAt(LIGHT_POS(i), LIGHT_SIZE(i), l, tmax, atten, k);
#endif
  return lightTerm(s, p, n, v, offset, LIGHT_COLOR(i), l, tmax, atten, k);
}
#endif

// Blinn-Phong radiance leaving surface point p (normal n, unit direction to
// the viewer v):
//   Ia*Ka*albedo*ao + sum_i lightTerm_i
// AO darkens only the ambient term. Compiles with NUM_LIGHTS 0. A
// specialized shader with one light calls it directly, with no loop; more
// lights share one loop, so the shadow march is compiled once.
vec3 shadeBlinnPhong(Surface s, vec3 p, vec3 n, vec3 v, float ao, float offset) {
#if ENV_MAP
  vec3 col = envIrradiance(n) * s.ka * s.albedo * ao;  // the map's diffuse light instead of Ia
#else
  vec3 col = uAmbient * s.ka * s.albedo * ao;
#endif
#if SPECIALIZED && NUM_LIGHTS == 1
  col += sceneLight(0, s, p, n, v, offset);
#elif NUM_LIGHTS > 0
  for (int i = 0; i < NUM_LIGHTS; ++i) col += sceneLight(i, s, p, n, v, offset);
#endif
  return col;
}
