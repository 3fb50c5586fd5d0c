// primitives_cones.glsl: solids of revolution around the y axis (cones, cut
// and hollow spheres). Each is the exact 2D distance of q = (|p.xz|, p.y) to
// its half profile, which is exact for the solid because the profile meets
// the axis. Included by primitives.glsl; claims as described there.
#pragma once
#include "common.glsl"

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCONE)
// Cone with its base disc of radius r at y = 0 and its apex at (0, h, 0):
// the nearer of the slanted side and the base. [exact; L = 1]
float sdCone(vec3 p, float r, float h) {
  vec2 q = vec2(length(p.xz), p.y - h);        // relative to the apex
  vec2 w = vec2(r, -h);                        // apex -> rim
  float side = msDot2(q - w * clamp(dot(q, w) / dot(w, w), 0.0, 1.0));
  float base = msDot2(q - vec2(clamp(q.x, 0.0, r), -h));
  bool inside = q.y > -h && q.x * h < -q.y * r;
  return (inside ? -1.0 : 1.0) * sqrt(min(side, base));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDINFINITECONE)
// Infinite cone, apex at the origin, opening towards +y with half angle
// theta < 90 degrees, sc = (sin, cos)(theta): the distance to the side ray
// on p's side of the axis. [exact; L = 1]
float sdInfiniteCone(vec3 p, vec2 sc) {
  vec2 q = vec2(length(p.xz), p.y);
  float d = length(q - sc * max(dot(q, sc), 0.0));
  return q.x * sc.y < q.y * sc.x ? -d : d;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCAPPEDCONE)
// Frustum around y: radius r1 at y = -h, r2 at y = +h. The nearest of the
// slanted side and both caps; inside between the caps and under the side.
// [exact; L = 1]
float sdCappedCone(vec3 p, float h, float r1, float r2) {
  vec2 q = vec2(length(p.xz), p.y);
  vec2 a = vec2(r1, -h), ba = vec2(r2 - r1, 2.0 * h);
  float side = msSegment2(q, a, a + ba);
  float bottom = msDot2(vec2(max(q.x - r1, 0.0), q.y + h));
  float top = msDot2(vec2(max(q.x - r2, 0.0), q.y - h));
  bool inside = abs(q.y) < h && msCross2(ba, q - a) > 0.0;
  return (inside ? -1.0 : 1.0) * sqrt(min(side, min(bottom, top)));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDROUNDCONE)
// The hull of a sphere of radius r1 at the origin and one of radius r2 at
// (0, h, 0), |r1 - r2| < h. The common tangent has unit normal (a, b) with
// b = (r1 - r2) / h; along the tangent, k < 0 is nearest the first sphere,
// k > a h the second, else the tangent line. [exact; L = 1]
float sdRoundCone(vec3 p, float r1, float r2, float h) {
  vec2 q = vec2(length(p.xz), p.y);
  float b = (r1 - r2) / h;
  float a = sqrt(max(1.0 - b * b, 0.0));
  float k = dot(q, vec2(-b, a));
  if (k < 0.0) return length(q) - r1;
  if (k > a * h) return length(q - vec2(0.0, h)) - r2;
  return dot(q, vec2(a, b)) - r1;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDSOLIDANGLE)
// A sphere sector: the ball of radius ra inside the cone of half angle theta
// around +y, sc = (sin, cos)(theta). max(sphere, +-distance to the cone's
// side segment), signed by the side of the cone p is on. [exact; L = 1]
float sdSolidAngle(vec3 p, vec2 sc, float ra) {
  vec2 q = vec2(length(p.xz), p.y);
  float l = length(q) - ra;
  float m = length(q - sc * clamp(dot(q, sc), 0.0, ra));
  return max(l, m * sign(sc.y * q.x - sc.x * q.y));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCUTSPHERE)
// A ball of radius r cut by the plane y = h (-r < h < r), keeping y < h.
// The boundary is the flat cap (radius w) and the arc below the rim; the
// arc's nearest point is along p's direction when that direction reaches
// the arc, else the rim. [exact; L = 1]
float sdCutSphere(vec3 p, float r, float h) {
  vec2 q = vec2(length(p.xz), p.y);
  float w = sqrt(max(r * r - h * h, 0.0));
  float cap = length(vec2(max(q.x - w, 0.0), q.y - h));
  float arc = r * q.y <= h * length(q) ? abs(length(q) - r) : length(q - vec2(w, h));
  bool inside = length(q) < r && q.y < h;
  return (inside ? -1.0 : 1.0) * min(cap, arc);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDCUTHOLLOWSPHERE)
// A spherical shell, radius r and half thickness t, cut by y = h (kept
// below): a tube of radius t around the arc below the rim. [exact; L = 1]
float sdCutHollowSphere(vec3 p, float r, float h, float t) {
  vec2 q = vec2(length(p.xz), p.y);
  float w = sqrt(max(r * r - h * h, 0.0));
  return (r * q.y <= h * length(q) ? abs(length(q) - r) : length(q - vec2(w, h))) - t;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDDEATHSTAR)
// A ball of radius ra at the origin with a ball of radius rb at (d, 0, 0)
// carved out (revolved around x). The spheres cross on the rim (a, b); in
// the wedge beyond it, between the rays from both centres through the rim,
// the rim is nearest; elsewhere the plain subtraction is exact.
// [exact; L = 1]
float sdDeathStar(vec3 p, float ra, float rb, float d) {
  vec2 q = vec2(p.x, length(p.yz));
  float a = (ra * ra - rb * rb + d * d) / (2.0 * d);
  float b = sqrt(max(ra * ra - a * a, 0.0));
  if (q.x * b - q.y * a > d * max(b - q.y, 0.0)) return length(q - vec2(a, b));
  return max(length(q) - ra, rb - length(q - vec2(d, 0.0)));
}
#endif
