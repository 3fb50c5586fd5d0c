// bounds_probe.glsl: with BOUNDS_PROBE 1, main.frag draws this instead of
// the image: the host's check that a scene's [bounds] hold everything map()
// draws (app/render/bounds_check.h). Pixel (x, y) of a kBoundsProbeN x
// 6 kBoundsProbeN target is one point on the bounds' surface: a grid on each
// of the box's six faces, or a Fibonacci spiral over the sphere. It writes
// vec4(point, map(point).x), with BIG instead where a declared plane is
// solid (what lies there is hidden by the plane anyway).
// main.frag has included bounds.glsl (the planes and the bounds' defines).
#pragma once

const int kBoundsProbeN = 64;   // app/render/bounds_check.cpp draws a target of this size

vec3 boundsProbePoint(ivec2 px) {
#if BOUNDS_KIND == 1
  const float golden = 2.39996323;                       // pi (3 - sqrt 5)
  float n = float(6 * kBoundsProbeN * kBoundsProbeN);
  float i = float(px.y * kBoundsProbeN + px.x) + 0.5;
  float z = 1.0 - 2.0 * i / n, r = sqrt(max(1.0 - z * z, 0.0));
  return BOUNDS_A.xyz + BOUNDS_A.w * vec3(r * cos(golden * i), r * sin(golden * i), z);
#elif BOUNDS_KIND == 2
  int face = px.y / kBoundsProbeN;
  vec2 uv = (vec2(px.x, px.y % kBoundsProbeN) + 0.5) / float(kBoundsProbeN);
  vec3 lo = BOUNDS_A.xyz, hi = BOUNDS_B.xyz;
  vec3 t = face < 2 ? vec3(float(face), uv) : face < 4 ? vec3(uv.x, float(face - 2), uv.y) : vec3(uv, float(face - 4));
  return mix(lo, hi, t);
#else
  return vec3(0.0);
#endif
}

void main() {
  vec3 p = boundsProbePoint(ivec2(gl_FragCoord.xy));
  outColor = vec4(p, planesMap(p).x < 0.0 ? BIG : map(p).x);
}
