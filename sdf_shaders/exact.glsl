// exact.glsl: exact ray-sphere intersection, for the sweep's exact-
// intersection reference image (docs/speed-vs-error.md). Compiled only when
// the host defines EXACT_SPHERES (a scene whose map() is a union of
// constant spheres, recognised by app/bench/sweep_exact.h):
//   EXACT_SPHERES            the number of spheres (1..)
//   EXACT_SPHERE_LIST        that many vec4(centre, radius)
//   EXACT_SPHERE_MATERIALS   their material ids
// trace() then intersects the spheres and the declared planes exactly and
// marches nothing; shading (normals, shadows, AO) still reads the field.
#pragma once
#include "bounds.glsl"

const vec4 kExactSpheres[EXACT_SPHERES] = vec4[EXACT_SPHERES](EXACT_SPHERE_LIST);
const int kExactSphereMaterials[EXACT_SPHERES] = int[EXACT_SPHERES](EXACT_SPHERE_MATERIALS);

// Nearest sphere hit of the ray o + t d (unit d) in [tmin, tmax]: shrinks
// tmax to it and returns its material, or -1. The root comes from the
// closest approach q (not b^2 - c), which keeps far spheres accurate in
// float. A ray that starts inside a sphere hits it at once, as marching does.
int intersectSpheres(vec3 o, vec3 d, float tmin, inout float tmax) {
  int mat = -1;
  for (int i = 0; i < EXACT_SPHERES; ++i) {
    vec3 oc = o - kExactSpheres[i].xyz;
    float r = kExactSpheres[i].w;
    float b = dot(oc, d);
    vec3 q = oc - b * d;
    float h2 = r * r - dot(q, q);
    if (h2 < 0.0) continue;
    float t = dot(oc, oc) <= r * r ? tmin : -b - sqrt(h2);
    if (t >= tmin && t <= tmax) {
      tmax = t;
      mat = kExactSphereMaterials[i];
    }
  }
  return mat;
}
