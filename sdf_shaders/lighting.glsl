// lighting.glsl: Blinn-Phong direct lighting over the scene's lights.
#pragma once

// Where light i comes from as seen from p: unit direction towards it (l),
// the distance a shadow ray may travel (tmax), the distance attenuation, and
// the penumbra sharpness k = 1/tan(angular radius of the light seen from p).
// Point: angular radius atan(size/dist), so k = dist/size; the shadow ray
// stops at the light's surface. Directional: angular radius = size; the
// shadow ray runs to MAX_DIST. Zero sizes and zero distances stay finite.
void lightAt(Light L, vec3 p, out vec3 l, out float tmax, out float atten, out float k) {
  if (L.pos.w > 0.5) {
    vec3 v = L.pos.xyz - p;
    float dist = length(v);
    l = safeNormalize(v, vec3(0.0, 1.0, 0.0));
    tmax = max(dist - L.size, 0.0);
    atten = 1.0 / max(L.atten.x + L.atten.y * dist + L.atten.z * dist * dist, 1e-6);
    k = shadowSharpness(L.size / max(dist, 1e-6));
  } else {
    l = -safeNormalize(L.pos.xyz, vec3(0.0, -1.0, 0.0));
    tmax = float(MAX_DIST);
    atten = 1.0;
    k = shadowSharpness(tan(clamp(L.size, 0.0, 1.4)));
  }
}

// Blinn-Phong radiance leaving surface point p (normal n, unit direction to
// the viewer v):
//   Ia*Ka*albedo*ao + sum_i Ip_i*(Kd*albedo*(N.L) + Ks*(H.N)^s) * atten_i * shadow_i
// with H = normalize(L + V). A light adds nothing where N.L <= 0 (and casts no
// shadow ray there). AO darkens only the ambient term. Shadow rays start at
// p + n*offset (offset: see main.frag). Compiles with NUM_LIGHTS 0.
vec3 shadeBlinnPhong(Surface s, vec3 p, vec3 n, vec3 v, float ao, float offset) {
  vec3 col = uAmbient * s.ka * s.albedo * ao;
#if NUM_LIGHTS > 0
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    vec3 l;
    float tmax, atten, k;
    lightAt(uLights[i], p, l, tmax, atten, k);
    float ndl = dot(n, l);
    if (ndl <= 0.0) continue;
    vec3 h = safeNormalize(l + v, n);
    float spec = s.ks * pow(max(dot(h, n), 0.0), s.shininess);
    float sh = softShadow(p + n * offset, l, tmax, k);
    col += uLights[i].color * (s.kd * s.albedo * ndl + spec) * (atten * sh);
  }
#endif
  return col;
}
