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
  // A NaN or Inf from map() is kept (max() with the cut would hide it):
  // the exporter counts such samples, as render counts such pixels.
  return vec2(isnan(m.x) || isinf(m.x) ? m.x : max(m.x, clip), m.y);
}

vec3 voxelPoint(ivec3 v) { return uFieldOrigin + uFieldVoxel * vec3(v); }

// Each invocation asks for one point at a time and is told the field
// there, so map() is inlined in one place: llvmpipe generates code for
// every place it is inlined, and a large graph's interpreter takes seconds
// to generate. Phases: 0 the first point (an edge's first end), 1 an
// edge's second end, 2 the root's refinements (regula falsi with the
// Illinois fix: the kept end's value halved; exact in one step on a
// plane), 3 the four taps of the gradient (central differences a
// hundredth of a voxel wide: the surface's own normal even a few
// hundredths of a voxel from a crease), 4 done.
const vec3 kTap[4] = vec3[4](vec3(1, -1, -1), vec3(-1, -1, 1), vec3(-1, 1, -1), vec3(1, 1, 1));

void main() {
  if (int(gl_GlobalInvocationID.x) >= uFieldCount) return;
  int g = uFieldBase + int(gl_GlobalInvocationID.x);
  int mode = uFieldMode;
  vec3 a = vec3(0.0), b = vec3(0.0);
  if (mode == 0) {
    int s = uBrick + 1, l = g % (s * s * s);
    a = voxelPoint(fieldIn[g / (s * s * s)].xyz + ivec3(l % s, (l / s) % s, l / (s * s)));
  } else if (mode == 1) {
    ivec4 c = fieldIn[g];
    a = uFieldOrigin + uFieldVoxel * (vec3(c.xyz) + 0.5 * float(c.w));
  } else if (mode == 2) {
    ivec4 e = fieldIn[g];
    a = voxelPoint(e.xyz);
    b = voxelPoint(e.xyz + ivec3(e.w == 0, e.w == 1, e.w == 2));
  } else {
    a = fieldPts[g].xyz;
  }
  float h = 0.01 * uFieldVoxel;
  int phase = 0, side = 0, iter = 0, tap = 0, calls = 0;
  float fa = 0.0, fb = 0.0, ta = 0.0, tb = 1.0, t = 0.0;
  vec3 tapAt = a, grad = vec3(0.0);
  vec2 first = vec2(0.0);
  for (int k = 0; k < 18 && phase < 4; ++k) {
    vec3 q = a;
    if (phase == 1) q = b;
    if (phase == 2) {
      t = (ta * fb - tb * fa) / (fb - fa);
      if (!(t > ta && t < tb)) t = 0.5 * (ta + tb);
      q = mix(a, b, t);
    }
    if (phase == 3) q = tapAt + kTap[tap] * h;
    vec2 v = fieldMap(q);
    ++calls;
    if (phase == 0) {
      first = v;
      fa = v.x;
      phase = mode == 2 ? 1 : mode == 3 ? 3 : 4;
    } else if (phase == 1) {
      fb = v.x;
      phase = 2;
    } else if (phase == 2) {
      ++iter;
      // A millionth of a voxel is as close as a float position gets.
      bool done = abs(v.x) <= 1e-6 * uFieldVoxel || tb - ta < 1e-6;
      if (!done) {
        if ((v.x < 0.0) == (fa < 0.0)) {
          ta = t; fa = v.x;
          if (side == -1) fb *= 0.5;
          side = -1;
        } else {
          tb = t; fb = v.x;
          if (side == 1) fa *= 0.5;
          side = 1;
        }
        if (iter == 12) t = (ta * fb - tb * fa) / (fb - fa);
      }
      if (done || iter == 12) {
        tapAt = mix(a, b, t);
        phase = 3;
      }
    } else {
      grad += kTap[tap] * v.x;
      if (++tap == 4) phase = 4;
    }
  }
  grad /= 4.0 * h;
  if (mode == 0 || mode == 1) {
    fieldOut[g] = first.x;
  } else if (mode == 2) {
    fieldOutV[g] = vec4(grad / max(length(grad), 1e-20), t);
    fieldOut[g] = float(calls);
  } else {
    fieldOutV[g] = vec4(grad, first.x);
    fieldOut[g] = first.y;
  }
}
