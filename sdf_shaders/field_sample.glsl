// field_sample.glsl: the mesh exporter's compute pass (app/render/field_sampler.h).
// The root has included the library and the scene's map(), exactly as the
// image's shader does, so the mesh is of the field the renderer draws.
// The field sampled is map() cut by the export's box (or sphere), so every
// surface closes; with uFieldPlanes the declared planes join the solid.
// Points are on a grid of voxels: voxel (i, j, k) at uFieldOrigin +
// uFieldVoxel * (i, j, k), computed the same way by every mode, so two
// modes that meet at a point read the same value.
//   mode 0 bricks: in[b] = brick's first voxel; out[b * S^3 + l] = field at its l-th corner (S = uBrick + 1)
//   mode 1 cells:  in[c] = (first voxel, side in voxels); out[c] = field at its centre
//   mode 2 edges:  in[e] = (voxel, axis); outV[e] = (unit gradient, t) at the root on the edge, t in [0, 1];
//                  out[e] = the map() calls it took
//   mode 3 points: pts[i] = world point; outV[i] = (gradient, field), out[i] = material id
//   mode 4 values: pts[i] = world point; outV[i].w = field, out[i] = material id (no gradient)
#pragma once
#include "bounds.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer FieldIn { ivec4 fieldIn[]; };
layout(std430, binding = 1) writeonly buffer FieldOut { float fieldOut[]; };
layout(std430, binding = 2) writeonly buffer FieldOutV { vec4 fieldOutV[]; };
layout(std430, binding = 8) readonly buffer FieldPoints { vec4 fieldPts[]; };

uniform int uFieldMode;
uniform int uFieldCount;   // invocations of this dispatch
uniform int uFieldBase;    // the first one's index: a long list is several dispatches
uniform int uBrick;          // cells along a brick's side
uniform vec3 uFieldOrigin;
uniform float uFieldVoxel;
uniform int uClipKind;       // 1 sphere (uClipA = centre, radius), 2 box (uClipA, uClipB = min, max)
uniform vec4 uClipA;
uniform vec4 uClipB;
uniform int uFieldPlanes;    // 1: the declared planes are part of the solid

vec2 fieldMap(vec3 p) {
  vec2 m = map(p);
#if NUM_PLANES > 0
  if (uFieldPlanes != 0) {
    vec2 pl = planesMap(p);
    if (pl.x < m.x) m = pl;
  }
#endif
  // The box's exact distance, written out: a specialized library may lack sdBox.
  vec3 q = abs(p - 0.5 * (uClipA.xyz + uClipB.xyz)) - 0.5 * (uClipB.xyz - uClipA.xyz);
  float box = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
  float clip = uClipKind == 1 ? length(p - uClipA.xyz) - uClipA.w : box;
  return vec2(max(m.x, clip), m.y);
}

vec3 voxelPoint(ivec3 v) { return uFieldOrigin + uFieldVoxel * vec3(v); }

// Central differences a hundredth of a voxel wide: close to the surface's
// own normal even a few hundredths of a voxel from a crease.
vec3 fieldGradient(vec3 p) {
  const vec2 k = vec2(1.0, -1.0);
  float h = 0.01 * uFieldVoxel;
  return (k.xyy * fieldMap(p + k.xyy * h).x + k.yyx * fieldMap(p + k.yyx * h).x +
          k.yxy * fieldMap(p + k.yxy * h).x + k.xxx * fieldMap(p + k.xxx * h).x) / (4.0 * h);
}

// The root of the field on a sign-changing edge: regula falsi with the
// Illinois fix (the kept end's value halved), exact in one step on a plane.
float edgeRoot(vec3 a, vec3 b, inout int calls) {
  calls += 2;
  float fa = fieldMap(a).x, fb = fieldMap(b).x;
  float ta = 0.0, tb = 1.0;
  int side = 0;
  for (int i = 0; i < 12; ++i) {
    float t = (ta * fb - tb * fa) / (fb - fa);
    if (!(t > ta && t < tb)) t = 0.5 * (ta + tb);
    float ft = fieldMap(mix(a, b, t)).x;
    ++calls;
    // A millionth of a voxel is as close as a float position gets.
    if (abs(ft) <= 1e-6 * uFieldVoxel || tb - ta < 1e-6) return t;
    if ((ft < 0.0) == (fa < 0.0)) {
      ta = t; fa = ft;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      tb = t; fb = ft;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return (ta * fb - tb * fa) / (fb - fa);
}

void main() {
  if (int(gl_GlobalInvocationID.x) >= uFieldCount) return;
  int g = uFieldBase + int(gl_GlobalInvocationID.x);
  if (uFieldMode == 0) {
    int s = uBrick + 1, l = g % (s * s * s);
    ivec3 v = fieldIn[g / (s * s * s)].xyz + ivec3(l % s, (l / s) % s, l / (s * s));
    fieldOut[g] = fieldMap(voxelPoint(v)).x;
  } else if (uFieldMode == 1) {
    ivec4 c = fieldIn[g];
    fieldOut[g] = fieldMap(uFieldOrigin + uFieldVoxel * (vec3(c.xyz) + 0.5 * float(c.w))).x;
  } else if (uFieldMode == 2) {
    ivec4 e = fieldIn[g];
    vec3 a = voxelPoint(e.xyz), b = voxelPoint(e.xyz + ivec3(e.w == 0, e.w == 1, e.w == 2));
    int calls = 4;
    float t = edgeRoot(a, b, calls);
    vec3 n = fieldGradient(mix(a, b, t));
    fieldOutV[g] = vec4(n / max(length(n), 1e-20), t);
    fieldOut[g] = float(calls);
  } else {
    vec3 p = fieldPts[g].xyz;
    vec2 m = fieldMap(p);
    fieldOutV[g] = vec4(uFieldMode == 3 ? fieldGradient(p) : vec3(0.0), m.x);
    fieldOut[g] = m.y;
  }
}
