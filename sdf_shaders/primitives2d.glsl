// primitives2d.glsl: signed distances of 2D shapes (sd2*, ud2* unsigned),
// in the plane of their vec2 argument. Turn them into solids with
// opExtrude(sd2X(p.xy, ...), p.z, h) or sd2X(domRevolve(p, o), ...), which
// keep an exact 2D distance exact. Included by primitives.glsl; claims as
// described there.
#pragma once
#include "common.glsl"

// The regular polygon is built on the star.
#if defined(USE_SD2REGULARPOLYGON) && !defined(USE_SD2STAR)
#define USE_SD2STAR 1
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2CIRCLE)
// Disc of radius r. [exact; L = 1]
float sd2Circle(vec2 p, float r) {
  return length(p) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2BOX)
// Rectangle with half extents b. [exact; L = 1]
float sd2Box(vec2 p, vec2 b) {
  return msBoxQ(abs(p) - b);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2ROUNDBOX)
// Rectangle with half extents b (rounding included), corners rounded with
// radius r <= min(b). [exact; L = 1]
float sd2RoundBox(vec2 p, vec2 b, float r) {
  return msBoxQ(abs(p) - b + r) - r;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_UD2SEGMENT)
// Distance to the segment a-b; minus a radius it is a 2D capsule (a stroke).
// [unsigned; L = 1]
float ud2Segment(vec2 p, vec2 a, vec2 b) {
  return sqrt(msSegment2(p, a, b));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2RHOMBUS)
// Rhombus with vertices (+-b.x, 0) and (0, +-b.y): folded to one quadrant,
// the distance to its edge there. [exact; L = 1]
float sd2Rhombus(vec2 p, vec2 b) {
  p = abs(p);
  vec2 a = vec2(b.x, 0.0), e = vec2(-b.x, b.y);
  float d = sqrt(msSegment2(p, a, a + e));
  return msCross2(e, p - a) > 0.0 ? -d : d;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2TRAPEZOID)
// Isosceles trapezoid: half width r1 at y = -h, r2 at y = +h. The nearest
// of the slanted side and both parallel sides. [exact; L = 1]
float sd2Trapezoid(vec2 p, float r1, float r2, float h) {
  p.x = abs(p.x);
  vec2 a = vec2(r1, -h), e = vec2(r2 - r1, 2.0 * h);
  float side = msSegment2(p, a, a + e);
  float caps = min(msDot2(vec2(max(p.x - r1, 0.0), p.y + h)), msDot2(vec2(max(p.x - r2, 0.0), p.y - h)));
  bool inside = abs(p.y) < h && msCross2(e, p - a) > 0.0;
  return (inside ? -1.0 : 1.0) * sqrt(min(side, caps));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2EQUILATERALTRIANGLE)
// Equilateral triangle centred on the origin with circumradius r, apex at
// (0, r). Folded by |x|: the nearer of the base and the right edge.
// [exact; L = 1]
float sd2EquilateralTriangle(vec2 p, float r) {
  p.x = abs(p.x);
  vec2 v1 = vec2(0.8660254 * r, -0.5 * r), v2 = vec2(0.0, r);
  float d = min(msSegment2(p, vec2(-v1.x, v1.y), v1), msSegment2(p, v1, v2));
  bool inside = p.y > v1.y && msCross2(v2 - v1, p - v1) > 0.0;
  return (inside ? -1.0 : 1.0) * sqrt(d);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2TRIANGLE)
// Any triangle a, b, c (either winding): the nearest edge, negative where p
// is on the inner side of all three. [exact; L = 1]
float sd2Triangle(vec2 p, vec2 a, vec2 b, vec2 c) {
  float d = min(min(msSegment2(p, a, b), msSegment2(p, b, c)), msSegment2(p, c, a));
  float s = sign(msCross2(b - a, c - a));
  bool inside = s * msCross2(b - a, p - a) > 0.0 && s * msCross2(c - b, p - b) > 0.0 &&
                s * msCross2(a - c, p - c) > 0.0;
  return (inside ? -1.0 : 1.0) * sqrt(d);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2HEXAGON)
// Regular hexagon with apothem r, flat sides at y = +-r. Folded by |x|, |y|
// and the 60-degree mirror, the nearest side is the top one.
// [exact; L = 1]
float sd2Hexagon(vec2 p, float r) {
  const vec2 n = vec2(0.8660254, -0.5);   // normal of the 60-degree mirror
  p = abs(p);
  p -= 2.0 * max(dot(p, n), 0.0) * n;
  vec2 q = p - vec2(clamp(p.x, -0.57735027 * r, 0.57735027 * r), r);
  return q.y < 0.0 ? -length(q) : length(q);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2STAR)
// Regular star with n points (n >= 3) of outer radius r and inner radius
// ri, one tip on +x. Folded by angle into the wedge between a tip and the
// next inner vertex, the distance to the edge joining them. [exact; L = 1]
float sd2Star(vec2 p, float r, float ri, float n) {
  float w = PI / n;                                   // half the angle between tips
  float a = mod(atan(p.y, p.x), 2.0 * w);
  a = a > w ? 2.0 * w - a : a;
  p = length(p) * vec2(cos(a), sin(a));
  vec2 tip = vec2(r, 0.0), e = ri * vec2(cos(w), sin(w)) - tip;
  float d = sqrt(msSegment2(p, tip, tip + e));
  return msCross2(e, p - tip) > 0.0 ? -d : d;
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2REGULARPOLYGON)
// Regular polygon with n sides (n >= 3) and circumradius r, one vertex on
// +x: a star whose inner vertices are the sides' midpoints, r cos(pi / n)
// from the centre. [exact; L = 1]
float sd2RegularPolygon(vec2 p, float r, float n) {
  return sd2Star(p, r, r * cos(PI / n), n);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2POLYGON)
// Polygon of the n vertices v[0] .. v[n - 1] (3 <= n <= 32, in either
// order; the rest of v is not read), simple (no edge crossing another):
// the nearest edge's distance, negative inside by the crossing rule.
// [exact; L = 1]
float sd2Polygon(vec2 p, float n, vec2 v[32]) {
  int m = int(n);
  float d = dot(p - v[0], p - v[0]), s = 1.0;
  for (int i = 0, j = m - 1; i < m; j = i, i++) {
    vec2 e = v[j] - v[i], w = p - v[i];
    d = min(d, msSegment2(p, v[i], v[j]));
    // An edge crossing the horizontal through p, on p's one side, flips it.
    bvec3 c = bvec3(p.y >= v[i].y, p.y < v[j].y, e.x * w.y > e.y * w.x);
    if (all(c) || all(not(c))) s = -s;
  }
  return s * sqrt(d);
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2PIE)
// Circular sector of radius r spanning theta either side of +y,
// sc = (sin, cos)(theta). [exact; L = 1]
float sd2Pie(vec2 p, vec2 sc, float r) {
  p.x = abs(p.x);
  float l = length(p) - r;
  float m = length(p - sc * clamp(dot(p, sc), 0.0, r));
  return max(l, m * sign(sc.y * p.x - sc.x * p.y));
}
#endif

#if !defined(MS_LIBRARY_SUBSET) || defined(USE_SD2ARC)
// An arc of radius ra spanning theta either side of +y (sc = (sin,
// cos)(theta)), stroked with half width rb: beyond the arc's ends the
// nearest spine point is the end. [exact; L = 1]
float sd2Arc(vec2 p, vec2 sc, float ra, float rb) {
  p.x = abs(p.x);
  return (sc.y * p.x > sc.x * p.y ? length(p - sc * ra) : abs(length(p) - ra)) - rb;
}
#endif
