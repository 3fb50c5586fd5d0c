// primitives_poly.glsl: polyhedra, prisms, the ellipsoid and flat shapes.
// Included by primitives.glsl; claims as described there.
#pragma once
#include "common.glsl"

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_UDTRIANGLE)
// Distance to the triangle a, b, c: to its plane where p projects inside
// (inside all three edges' inward normals), else to the nearest edge.
// [unsigned; L = 1]
float udTriangle(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 n = cross(b - a, c - a);
  bool inside = dot(cross(n, b - a), p - a) >= 0.0 && dot(cross(n, c - b), p - b) >= 0.0 &&
                dot(cross(n, a - c), p - c) >= 0.0;
  if (inside && dot(n, n) > 1e-20) return abs(dot(n, p - a)) * inversesqrt(dot(n, n));
  return sqrt(min(min(msSegment2(p, a, b), msSegment2(p, b, c)), msSegment2(p, c, a)));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_UDQUAD)
// Distance to the planar convex quad a, b, c, d (in order): as udTriangle,
// with four edges. [unsigned; L = 1]
float udQuad(vec3 p, vec3 a, vec3 b, vec3 c, vec3 d) {
  vec3 n = cross(b - a, d - a);
  bool inside = dot(cross(n, b - a), p - a) >= 0.0 && dot(cross(n, c - b), p - b) >= 0.0 &&
                dot(cross(n, d - c), p - c) >= 0.0 && dot(cross(n, a - d), p - d) >= 0.0;
  if (inside && dot(n, n) > 1e-20) return abs(dot(n, p - a)) * inversesqrt(dot(n, n));
  return sqrt(min(min(msSegment2(p, a, b), msSegment2(p, b, c)), min(msSegment2(p, c, d), msSegment2(p, d, a))));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDELLIPSOID)
// Ellipsoid with semi-axes r (no closed-form distance: it needs a quartic).
// Outside, the first-order estimate f / |grad f| of f = |p / r| - 1, close
// near the surface; inside, where that estimate overshoots and grows too
// fast, (|p / r| - 1) min(r): the map p -> p / r shrinks distances by at
// most 1 / min(r). [bound; L = 1]
float sdEllipsoid(vec3 p, vec3 r) {
  float k0 = length(p / r);
  if (k0 < 1.0) return (k0 - 1.0) * min(r.x, min(r.y, r.z));
  return k0 * (k0 - 1.0) / length(p / (r * r));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDOCTAHEDRON)
// Octahedron |x| + |y| + |z| <= s. Folded to the positive octant the face
// is x + y + z = s; where p projects inside it the distance is the plane's,
// else (3 p_i < m) the nearest point lies on the face's edge in the plane
// p_i = 0. [exact; L = 1]
float sdOctahedron(vec3 p, float s) {
  p = abs(p);
  float m = p.x + p.y + p.z - s;
  vec3 q;
  if (3.0 * p.x < m) q = p.xyz;
  else if (3.0 * p.y < m) q = p.yzx;
  else if (3.0 * p.z < m) q = p.zxy;
  else return m * 0.57735027;
  float t = clamp(0.5 * (q.z - q.y + s), 0.0, s);
  return length(vec3(q.x, q.y - s + t, q.z - t));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDPYRAMID)
// Square pyramid: base of side 1 centred on the origin in y = 0, apex at
// (0, h, 0). Folded by its symmetry (|x|, |z|, then x >= z) the nearest
// surface is the +x face's triangle or the base. [exact; L = 1]
float sdPyramid(vec3 p, float h) {
  p.xz = abs(p.xz);
  if (p.z > p.x) p.xz = p.zx;
  float face = udTriangle(p, vec3(0.0, h, 0.0), vec3(0.5, 0.0, 0.5), vec3(0.5, 0.0, -0.5));
  float base = length(vec3(max(p.x - 0.5, 0.0), p.y, max(p.z - 0.5, 0.0)));
  bool inside = p.y > 0.0 && h * p.x + 0.5 * p.y < 0.5 * h;
  return (inside ? -1.0 : 1.0) * min(face, base);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDHEXPRISM)
// Hexagonal prism along z: a regular hexagon in xy with apothem h.x (flat
// sides at y = +-h.x), half length h.y. The exact 2D hexagon, extruded
// exactly. [exact; L = 1]
float sdHexPrism(vec3 p, vec2 h) {
  return msBoxQ(vec2(sd2Hexagon(p.xy, h.x), abs(p.z) - h.y));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDTRIPRISM)
// Triangular prism along z: an equilateral triangle in xy with
// circumradius h.x (apex towards +y), half length h.y. [exact; L = 1]
float sdTriPrism(vec3 p, vec2 h) {
  return msBoxQ(vec2(sd2EquilateralTriangle(p.xy, h.x), abs(p.z) - h.y));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDRHOMBUS)
// A rhombus slab: the rhombus with half diagonals la (x) and lb (z) grown by
// ra (rounded sides), half thickness h along y. [exact; L = 1]
float sdRhombus(vec3 p, float la, float lb, float h, float ra) {
  return msBoxQ(vec2(sd2Rhombus(p.xz, vec2(la, lb)) - ra, abs(p.y) - h));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDDODECAHEDRON)
// Regular dodecahedron with inradius r: the farthest of its 6 face planes
// (normals (0, 1, phi) cycled, both signs through abs). Exact inside, too
// small near edges and vertices outside. [bound; L = 1]
float sdDodecahedron(vec3 p, float r) {
  const vec3 n = vec3(0.0, 0.52573111, 0.85065081);   // (0, 1, phi) / |.|
  p = abs(p);
  return max(max(dot(p, n), dot(p, n.yzx)), dot(p, n.zxy)) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SDICOSAHEDRON)
// Regular icosahedron with inradius r: the farthest of its 10 face planes
// (normals (1, 1, 1) and (0, 1/phi, phi) cycled, / sqrt 3). Exact inside,
// too small near edges and vertices outside. [bound; L = 1]
float sdIcosahedron(vec3 p, float r) {
  const vec3 n = vec3(0.0, 0.35682209, 0.93417236);   // (0, 1/phi, phi) / sqrt 3
  p = abs(p);
  float d = dot(p, vec3(0.57735027));
  d = max(d, max(max(dot(p, n), dot(p, n.yzx)), dot(p, n.zxy)));
  return d - r;
}
#endif
