#include "scene/graph_vocab.h"

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

namespace ms {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kSqrt2 = 1.41421356f;
// The circumradius of a regular dodecahedron or icosahedron over its
// inradius (the same for both: they are dual).
constexpr float kPlatonicR = 1.25841f;

GraphBox sym(float x, float y, float z) { return {{-x, -y, -z}, {x, y, z}}; }
GraphBox span(glm::vec3 lo, glm::vec3 hi) { return {lo, hi}; }
glm::vec3 v3(const float* p) { return {p[0], p[1], p[2]}; }
GraphBox points(std::initializer_list<glm::vec3> ps, float r) {
  GraphBox b;
  for (glm::vec3 p : ps) {
    b.min = glm::min(b.min, p - r);
    b.max = glm::max(b.max, p + r);
  }
  return b;
}

GraphBox points2(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return {{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), 0.0f},
          {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), 0.0f}};
}

GraphParam pos(std::string_view n, int size = 3) { return {n, size, false, true}; }
GraphParam len(std::string_view n, int size = 1) { return {n, size, true, true}; }
GraphParam any(std::string_view n, int size = 1) { return {n, size, false, false}; }
GraphParam range(std::string_view n) { return {n, 2, false, true, true}; }
GraphParam unit(std::string_view n) { return {n, 3, false, false, false, true}; }
GraphParam vertices(std::string_view n) {
  GraphParam v{n, 1 + 2 * kPolygonPoints, false, false};
  v.points = kPolygonPoints;
  return v;
}
// A vertex list's box (count first, then the pairs).
GraphBox polygon_box(const float* p) {
  GraphBox b{{kInf, kInf, 0.0f}, {-kInf, -kInf, 0.0f}};
  for (int i = 0; i < static_cast<int>(p[0]); ++i)
    for (int a = 0; a < 2; ++a) {
      b.min[a] = std::min(b.min[a], p[1 + 2 * i + a]);
      b.max[a] = std::max(b.max[a], p[1 + 2 * i + a]);
    }
  return b;
}

// A range's end as a box coordinate: an open end is infinite.
float bound(float v) { return std::fabs(v) >= kOpenBound ? std::copysign(kInf, v) : v; }
// The half-space dot(p, n) + w <= 0 bounds the axis n lies along, if any.
GraphBox half_space(const float* p) {
  GraphBox b = sym(kInf, kInf, kInf);
  for (int i = 0; i < 3; ++i)
    if (p[(i + 1) % 3] == 0.0f && p[(i + 2) % 3] == 0.0f) {
      if (p[i] > 0.0f) b.max[i] = -p[3] / p[i];
      if (p[i] < 0.0f) b.min[i] = -p[3] / p[i];
    }
  return b;
}

const std::vector<GraphPrimitive>& primitives() {
  using P = const float*;
  static const std::vector<GraphPrimitive> v = {
      {"sdSphere", {len("r")}, 1, [](P p) { return sym(p[0], p[0], p[0]); }},
      {"sdPlane", {unit("n"), pos("w", 1)}, 1, half_space},
      {"sdSlab", {range("x"), range("y"), range("z")}, 1,
       [](P p) { return span({bound(p[0]), bound(p[2]), bound(p[4])}, {bound(p[1]), bound(p[3]), bound(p[5])}); }},
      {"sdBox", {len("b", 3)}, 1, [](P p) { return sym(p[0], p[1], p[2]); }},
      {"sdBoxCheap", {len("b", 3)}, 1, [](P p) { return sym(p[0], p[1], p[2]); }},
      {"sdRoundBox", {len("b", 3), len("r")}, 1, [](P p) { return sym(p[0], p[1], p[2]); }},
      {"sdBoxFrame", {len("b", 3), len("e")}, 1, [](P p) { return sym(p[0], p[1], p[2]); }},
      {"sdTorus", {len("t", 2)}, 1, [](P p) { return sym(p[0] + p[1], p[1], p[0] + p[1]); }},
      {"sdCappedTorus", {any("sc", 2), len("ra"), len("rb")}, 1,
       [](P p) { return sym(p[2] + p[3], p[2] + p[3], p[2] + p[3]); }},
      {"sdLink", {len("le"), len("r1"), len("r2")}, 1,
       [](P p) { return sym(p[1] + p[2], p[0] + p[1] + p[2], p[2]); }},
      {"sdCapsule", {pos("a"), pos("b"), len("r")}, 1, [](P p) { return points({v3(p), v3(p + 3)}, p[6]); }},
      {"sdVerticalCapsule", {len("h"), len("r")}, 1,
       [](P p) { return span({-p[1], -p[1], -p[1]}, {p[1], p[0] + p[1], p[1]}); }},
      {"sdCylinder", {len("r"), len("h")}, 1, [](P p) { return sym(p[0], p[1], p[0]); }},
      {"sdInfiniteCylinder", {pos("c")}, 1,
       [](P p) { return span({p[0] - p[2], -kInf, p[1] - p[2]}, {p[0] + p[2], kInf, p[1] + p[2]}); }},
      {"sdCappedCylinder", {pos("a"), pos("b"), len("r")}, 1, [](P p) { return points({v3(p), v3(p + 3)}, p[6]); }},
      {"sdRoundedCylinder", {len("r"), len("h"), len("e")}, 1, [](P p) { return sym(p[0], p[1], p[0]); }},
      {"sdCone", {len("r"), len("h")}, 1, [](P p) { return span({-p[0], 0, -p[0]}, {p[0], p[1], p[0]}); }},
      {"sdInfiniteCone", {any("sc", 2)}, 1, [](P) { return sym(kInf, kInf, kInf); }},
      {"sdCappedCone", {len("h"), len("r1"), len("r2")}, 1,
       [](P p) { const float r = std::max(p[1], p[2]); return sym(r, p[0], r); }},
      {"sdRoundCone", {len("r1"), len("r2"), len("h")}, 1,
       [](P p) {
         const float r = std::max(p[0], p[1]);
         return span({-r, -p[0], -r}, {r, p[2] + p[1], r});
       }},
      {"sdSolidAngle", {any("sc", 2), len("ra")}, 1, [](P p) { return sym(p[2], p[2], p[2]); }},
      {"sdCutSphere", {len("r"), pos("h", 1)}, 1, [](P p) { return sym(p[0], p[0], p[0]); }},
      {"sdCutHollowSphere", {len("r"), pos("h", 1), len("t")}, 1,
       [](P p) { return sym(p[0] + p[2], p[0] + p[2], p[0] + p[2]); }},
      {"sdDeathStar", {len("ra"), len("rb"), pos("d", 1)}, 1, [](P p) { return sym(p[0], p[0], p[0]); }},
      {"udTriangle", {pos("a"), pos("b"), pos("c")}, 1, [](P p) { return points({v3(p), v3(p + 3), v3(p + 6)}, 0); }},
      {"udQuad", {pos("a"), pos("b"), pos("c"), pos("d")}, 1,
       [](P p) { return points({v3(p), v3(p + 3), v3(p + 6), v3(p + 9)}, 0); }},
      {"sdEllipsoid", {len("r", 3)}, 1, [](P p) { return sym(p[0], p[1], p[2]); }},
      {"sdOctahedron", {len("s")}, 1, [](P p) { return sym(p[0], p[0], p[0]); }},
      {"sdPyramid", {len("h")}, 1, [](P p) { return span({-0.5f, 0, -0.5f}, {0.5f, p[0], 0.5f}); }},
      // The hexagon's corners lie at 2 / sqrt 3 of its apothem.
      {"sdHexPrism", {len("h", 2)}, 1, [](P p) { return sym(p[0] * 1.1547006f, p[0], p[1]); }},
      {"sdTriPrism", {len("h", 2)}, 1, [](P p) { return sym(p[0], p[0], p[1]); }},
      {"sdRhombus", {len("la"), len("lb"), len("h"), len("ra")}, 1,
       [](P p) { return sym(p[0] + p[3], p[2], p[1] + p[3]); }},
      {"sdDodecahedron", {len("r")}, 1, [](P p) { const float r = p[0] * kPlatonicR; return sym(r, r, r); }},
      {"sdIcosahedron", {len("r")}, 1, [](P p) { const float r = p[0] * kPlatonicR; return sym(r, r, r); }},
      // Profiles: shapes of p.xy, solids only through extrude or revolve.
      {"sd2Circle", {len("r")}, 1, [](P p) { return sym(p[0], p[0], 0); }, 2},
      {"sd2Box", {len("b", 2)}, 1, [](P p) { return sym(p[0], p[1], 0); }, 2},
      {"sd2RoundBox", {len("b", 2), len("r")}, 1, [](P p) { return sym(p[0], p[1], 0); }, 2},
      {"ud2Segment", {pos("a", 2), pos("b", 2)}, 1, [](P p) { return points2({p[0], p[1]}, {p[2], p[3]}, {p[2], p[3]}); }, 2},
      {"sd2Rhombus", {len("b", 2)}, 1, [](P p) { return sym(p[0], p[1], 0); }, 2},
      {"sd2Trapezoid", {len("r1"), len("r2"), len("h")}, 1, [](P p) { return sym(std::max(p[0], p[1]), p[2], 0); }, 2},
      {"sd2EquilateralTriangle", {len("r")}, 1, [](P p) { return sym(p[0], p[0], 0); }, 2},
      {"sd2Triangle", {pos("a", 2), pos("b", 2), pos("c", 2)}, 1,
       [](P p) { return points2({p[0], p[1]}, {p[2], p[3]}, {p[4], p[5]}); }, 2},
      // The hexagon's corners lie at 2 / sqrt 3 of its apothem.
      {"sd2Hexagon", {len("r")}, 1, [](P p) { return sym(p[0] * 1.1547006f, p[0] * 1.1547006f, 0); }, 2},
      {"sd2Star", {len("r"), len("ri"), {"n", 1, true, false}}, 1,
       [](P p) { const float r = std::max(p[0], p[1]); return sym(r, r, 0); }, 2},
      {"sd2RegularPolygon", {len("r"), {"n", 1, true, false}}, 1, [](P p) { return sym(p[0], p[0], 0); }, 2},
      {"sd2Polygon", {vertices("v")}, 1, polygon_box, 2},
      {"sd2Pie", {any("sc", 2), len("r")}, 1, [](P p) { return sym(p[2], p[2], 0); }, 2},
      {"sd2Arc", {any("sc", 2), len("ra"), len("rb")}, 1, [](P p) { return sym(p[2] + p[3], p[2] + p[3], 0); }, 2},
  };
  return v;
}

using N = const GraphNode&;
using P = const float*;

// Union-like: outside both cores min(a, b) is at least the distance to
// their union minus the larger slack; a blend lowers that by `by`.
void union_box(N a, N b, GraphNode& out, float slack) {
  out.core = box_union(a.core, b.core);
  out.slack = slack;
}
// A quadratic smooth union is min(a, b) - k/4 at worst, and when one side
// is outside-exact (slack 0) at least min(a, b) - max(k, the other's slack):
// a left-folded chain of blends stays within one k.
float smooth_slack(N a, N b, float k) {
  const float worst = std::max(a.slack, b.slack) + 0.25f * k;
  if (std::min(a.slack, b.slack) > 0.0f) return worst;
  return std::min(worst, std::max(std::max(a.slack, b.slack), k));
}
// Inside both (or inside a): the children's boxes intersected; treated as
// outside-exact (slack 0), as the library's intersections of exact fields
// nearly are.
void inside_box(const GraphBox& a, const GraphBox& b, GraphNode& out) {
  out.core = box_intersection(a, b);
  out.slack = 0.0f;
}
GraphBox full(N n, float extra = 0.0f) { return box_grow(n.core, n.slack + extra); }

// Reaches (graph_vocab.h), each derived from sdf_shaders/combinators.glsl
// so that op(a, b) returns the kept child's own float (min and max pick an
// argument) wherever the rule drops the other: pruning changes no bit.
// - the quadratic smin is min(a, b) once |a - b| >= k; the rounded corner
//   once b >= max(a, r); the chamfer line a + b = r lies above b = a once
//   b - a >= r - (2 - sqrt 2) a, the worst a being the cell's highest.
// - columns: each column is a disc of radius r / (sqrt 2 n) centred on the
//   chamfer line, so its field is at least the chamfer's moved out by that
//   radius, (a + b - r (1 + 1/n)) / sqrt 2: the chamfer's rule with
//   r (1 + 1/n). It is met with equality where a column's centre lies
//   straight across the line, and holds for whichever column the GLSL picks.
// - stairs: each step's quarter plane a < x_i, b < y_i has a field of at
//   least b - y_i, and the highest corner is y = r - r / (2n): so b - a >=
//   r - r / (2n) leaves a (with equality below the first step's x), and a
//   and b swapped likewise; it holds for whichever three steps are looked at.
// - pipe: length(a, b) - r is neither child anywhere: no rule.
// - engrave, groove and tongue are a wherever b is far enough from its
//   surface, the least |b| being: max(a, (a + r - |b|) / sqrt 2) == a iff
//   |b| >= r - (sqrt 2 - 1) a, worst at the lowest a; max(a, min(a + ra,
//   rb - |b|)) == a iff |b| >= rb - a, the lowest a; min(a, max(a - ra,
//   |b| - rb)) == a iff |b| >= rb + a, the highest a. Exact conditions: b
//   is kept only where some a of the interval needs it.
constexpr std::string_view kReachMin = "0.0";
constexpr std::string_view kReachK = "P0";
constexpr std::string_view kReachRound = "max(0.0, P0 - AHI)";
constexpr std::string_view kReachChamfer = "max(0.0, P0 - 0.58578644 * AHI)";
constexpr std::string_view kReachColumns = "max(0.0, P0 * (1.0 + 1.0 / P1) - 0.58578644 * AHI)";
constexpr std::string_view kReachStairs = "P0 - 0.5 * P0 / P1";
constexpr std::string_view kReachEngrave = "P0 - 0.41421356 * ALO";
constexpr std::string_view kReachGroove = "P1 - ALO";
constexpr std::string_view kReachTongue = "P1 + AHI";
constexpr std::string_view kNever = "";

const std::vector<GraphOperator>& operators() {
  const auto uni = [](N a, N b, P, GraphNode& o) { union_box(a, b, o, std::max(a.slack, b.slack)); };
  const auto inter = [](N a, N b, P, GraphNode& o) { inside_box(full(a), full(b), o); };
  const auto sub = [](N a, N, P, GraphNode& o) { inside_box(full(a), full(a), o); };
  const auto smooth = [](N a, N b, P p, GraphNode& o) { union_box(a, b, o, smooth_slack(a, b, p[0])); };
  const auto by_r = [](N a, N b, P p, GraphNode& o) { union_box(a, b, o, std::max(a.slack, b.slack) + p[0]); };
  static const std::vector<GraphOperator> v = {
      {"opUnion", {}, 1, OpFamily::union_, uni, kReachMin},
      {"opIntersection", {}, 1, OpFamily::intersection, inter, kReachMin},
      {"opSubtraction", {}, 1, OpFamily::subtraction, sub, kReachMin},
      {"opSmoothUnion", {len("k")}, 1, OpFamily::union_, smooth, kReachK},
      {"opSmoothIntersection", {len("k")}, 1, OpFamily::intersection, inter, kReachK},
      {"opSmoothSubtraction", {len("k")}, 1, OpFamily::subtraction, sub, kReachK},
      {"opUnionChamfer", {len("r")}, kSqrt2, OpFamily::union_, by_r, kReachChamfer},
      {"opIntersectionChamfer", {len("r")}, kSqrt2, OpFamily::intersection, inter, kReachChamfer},
      {"opSubtractionChamfer", {len("r")}, kSqrt2, OpFamily::subtraction, sub, kReachChamfer},
      {"opUnionRound", {len("r")}, kSqrt2, OpFamily::union_, by_r, kReachRound},
      {"opIntersectionRound", {len("r")}, kSqrt2, OpFamily::intersection, inter, kReachRound},
      {"opSubtractionRound", {len("r")}, kSqrt2, OpFamily::subtraction, sub, kReachRound},
      {"opUnionColumns", {len("r"), {"n", 1, true, false}}, kSqrt2, OpFamily::union_, by_r, kReachColumns},
      {"opUnionStairs", {len("r"), {"n", 1, true, false}}, kSqrt2, OpFamily::union_, by_r, kReachStairs},
      // Where |a| <= r and |b| <= r: near both surfaces.
      {"opPipe", {len("r")}, kSqrt2, OpFamily::other,
       [](N a, N b, P p, GraphNode& o) { inside_box(full(a, p[0]), full(b, p[0]), o); }, kNever},
      {"opEngrave", {len("r")}, kSqrt2, OpFamily::other, sub, kReachEngrave},
      {"opGroove", {len("ra"), len("rb")}, 1, OpFamily::other, sub, kReachGroove},
      {"opTongue", {len("ra"), len("rb")}, 1, OpFamily::other,
       [](N a, N, P p, GraphNode& o) { inside_box(full(a, p[0]), full(a, p[0]), o); }, kReachTongue},
      // (1 - t) a + t b is negative only where a or b is, and a weighted
      // mean of two values above a floor stays above it. Never equal to
      // one child (for 0 < t < 1), so it keeps both, as the pipe does.
      {"opBlend", {[] { GraphParam t{"t", 1, true, false}; t.fraction = true; return t; }()}, 1, OpFamily::other, uni, kNever},
  };
  return v;
}

template <class T>
int find_in(const std::vector<T>& v, std::string_view name) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

bool GraphBox::finite() const {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(min[i]) || !std::isfinite(max[i])) return false;
  return true;
}

GraphBox box_union(const GraphBox& a, const GraphBox& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }
GraphBox box_intersection(const GraphBox& a, const GraphBox& b) {
  return {glm::max(a.min, b.min), glm::min(a.max, b.max)};
}
GraphBox box_grow(const GraphBox& a, float by) {
  if (a.empty()) return a;
  return {a.min - by, a.max + by};
}

std::span<const GraphPrimitive> graph_primitives() { return primitives(); }
std::span<const GraphOperator> graph_operators() { return operators(); }
int find_primitive(std::string_view name) { return find_in(primitives(), name); }
int find_operator(std::string_view name) { return find_in(operators(), name); }
int param_floats(const std::vector<GraphParam>& params) {
  int n = 0;
  for (const GraphParam& p : params) n += p.size;
  return n;
}

}  // namespace ms
