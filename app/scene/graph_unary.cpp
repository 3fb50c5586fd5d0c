#include "scene/graph_unary.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ms {

namespace {

using N = const GraphNode&;
constexpr float kInf = std::numeric_limits<float>::infinity();

GraphParam len(std::string_view n, int size = 1) { return {n, size, true, true}; }
GraphParam any(std::string_view n, int size = 1) { return {n, size, false, false}; }
GraphParam derived(std::string_view n, int size = 1) {
  GraphParam p{n, size, false, false};
  p.derived = true;
  return p;
}
GraphParam axis(std::string_view n, float x, float y, float z) {
  GraphParam p{n, 3, false, false, false, true};
  p.optional = true;
  p.fallback[0] = x, p.fallback[1] = y, p.fallback[2] = z;
  return p;
}
GraphParam counts(std::string_view n) {
  GraphParam p{n, 3, false, false};
  p.optional = true;
  p.fallback[0] = p.fallback[1] = p.fallback[2] = -1.0f;
  return p;
}

GraphBox full(N n) { return box_grow(n.core, n.slack); }
// A box coordinate as the GLSL takes it: an open side is the library's BIG.
float finite(float v) { return std::isfinite(v) ? v : std::copysign(kOpenBound, v); }
void put(float* at, glm::vec3 v) {
  for (int i = 0; i < 3; ++i) at[i] = finite(v[i]);
}
glm::vec3 corner(const GraphBox& b, int k) {
  return {k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z};
}
// The least box around a cylinder about unit `axis` of radius r whose axis
// runs from t0 to t1 along it.
GraphBox cylinder_box(glm::vec3 axis, float r, float t0, float t1) {
  GraphBox b;
  for (int i = 0; i < 3; ++i) {
    const float spread = r * std::sqrt(std::max(0.0f, 1.0f - axis[i] * axis[i]));
    const float a = axis[i] == 0.0f ? 0.0f : axis[i] * t0, c = axis[i] == 0.0f ? 0.0f : axis[i] * t1;
    b.min[i] = std::min(a, c) - spread;
    b.max[i] = std::max(a, c) + spread;
  }
  return b;
}
// The farthest a box's corners lie from the unit axis, and its extent along
// it; false where that is infinite. An axis along x, y or z may have
// infinite sides along itself.
bool radial(const GraphBox& b, glm::vec3 axis, float& r, float& t0, float& t1) {
  r = 0.0f, t0 = kInf, t1 = -kInf;
  for (int i = 0; i < 3; ++i)
    if (std::fabs(axis[i]) == 1.0f) {
      const int u = (i + 1) % 3, v = (i + 2) % 3;
      const float x = std::max(std::fabs(b.min[u]), std::fabs(b.max[u]));
      const float y = std::max(std::fabs(b.min[v]), std::fabs(b.max[v]));
      r = std::sqrt(x * x + y * y);
      t0 = axis[i] > 0.0f ? b.min[i] : -b.max[i];
      t1 = axis[i] > 0.0f ? b.max[i] : -b.min[i];
      return std::isfinite(r);
    }
  if (!b.finite()) return false;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 c = corner(b, k);
    const float along = glm::dot(c, axis);
    r = std::max(r, glm::length(c - axis * along));
    t0 = std::min(t0, along), t1 = std::max(t1, along);
  }
  return true;
}

// A warp about an axis (twist, bend): its box is the cylinder of radius r
// its child lies in, from t0 to t1 along the axis, its bound l; the
// derived r, l and box go at `at`.
void cylinder_warp(glm::vec3 axis, float r, float t0, float t1, float l, float* at, GraphNode& out) {
  out.core = cylinder_box(axis, r, t0, t1);
  out.slack = 0.0f;
  out.lipschitz = l;
  at[0] = r, at[1] = l;
  put(at + 2, out.core.min);
  put(at + 5, out.core.max);
}

std::string twist(N c, float* p, GraphNode& out) {
  const glm::vec3 ax{p[1], p[2], p[3]};
  float r, t0, t1;
  if (!radial(full(c), ax, r, t0, t1)) return "its child's box must be bounded across the twist's axis";
  const float a = std::fabs(p[0]) * r;
  cylinder_warp(ax, r, t0, t1, 0.5f * (a + std::sqrt(a * a + 4.0f)), p + 4, out);
  return {};
}

std::string bend(N c, float* p, GraphNode& out) {
  float r, t0, t1;
  if (!radial(full(c), {0, 0, 1}, r, t0, t1)) return "its child's box must be bounded in x and y";
  cylinder_warp({0, 0, 1}, r, t0, t1, 1.0f + std::fabs(p[0]) * r, p + 1, out);
  return {};
}

std::string elongate(N c, float* p, GraphNode& out) {
  const glm::vec3 h{p[0], p[1], p[2]};
  out.core = {c.core.min - h, c.core.max + h};
  out.slack = c.slack;
  return {};
}

std::string scale(N c, float* p, GraphNode& out) {
  const glm::vec3 s{p[0], p[1], p[2]};
  if (!(std::min({s.x, s.y, s.z}) > 0.0f)) return "'s' must be > 0 along every axis";
  const GraphBox b = full(c);
  out.core = {b.min * s, b.max * s};
  out.slack = 0.0f;
  p[3] = std::min({s.x, s.y, s.z});
  put(p + 4, out.core.min);
  put(p + 7, out.core.max);
  return {};
}

// The copies' floor parameters (kCopyFloorFloats) at `at`.
void copy_floor(N c, float* at) {
  put(at, c.core.min);
  put(at + 3, c.core.max);
  at[6] = c.slack;
}

std::string repeat(N c, float* p, GraphNode& out) {
  if (c.core.empty() || !full(c).finite()) return "its child must be bounded";
  out.core = c.core;
  out.slack = c.slack;
  // The copies a point may look at: along each axis those whose box can
  // hold the nearest surface (modifiers.glsl), at most every copy there is.
  double looked = 1.0;
  for (int i = 0; i < 3; ++i) {
    const float s = p[i], n = p[3 + i];
    if (n >= 0.0f && n != std::floor(n)) return "'count' must be whole numbers (copies either side), or -1 for no end";
    if (s == 0.0f) continue;
    const double reach = (double(c.core.max[i]) - c.core.min[i] + 2.0 * c.slack) / s + 2.0;
    looked *= n < 0.0f ? reach : std::min(reach, 2.0 * n + 1.0);
    if (n < 0.0f) out.core.min[i] = -kInf, out.core.max[i] = kInf;
    else out.core.min[i] -= n * s, out.core.max[i] += n * s;
  }
  if (looked > kMaxCopies)
    return "a point would look at up to " + std::to_string(static_cast<long long>(looked)) + " copies (at most " +
           std::to_string(kMaxCopies) + "): the spacing is small against the child's size";
  copy_floor(c, p + 6);
  return {};
}

std::string polar(N c, float* p, GraphNode& out) {
  if (!(p[0] >= 1.0f && p[0] == std::floor(p[0]))) return "'count' must be a whole number of copies, 1 or more";
  if (p[0] > kMaxCopies) return "'count' must be at most " + std::to_string(kMaxCopies) + ": a point looks at every copy";
  const glm::vec3 ax{p[2], p[3], p[4]};
  // Copies go out along the part of +x across the axis (+y for an x axis).
  glm::vec3 across = glm::vec3(1, 0, 0) - ax * ax.x;
  if (glm::length(across) < 1e-3f) across = glm::vec3(0, 1, 0) - ax * ax.y;
  across = glm::normalize(across);
  p[5] = across.x, p[6] = across.y, p[7] = across.z;
  GraphBox moved = full(c);
  moved.min += across * p[1], moved.max += across * p[1];
  // Guard the corner order for a negative component of `across`.
  GraphBox b{glm::min(moved.min, moved.max), glm::max(moved.min, moved.max)};
  float r, t0, t1;
  if (!radial(b, ax, r, t0, t1)) return "its child must be bounded";
  out.core = cylinder_box(ax, r, t0, t1);
  out.slack = 0.0f;
  copy_floor(c, p + 8);
  return {};
}

std::string mirror(N c, float* p, GraphNode& out) {
  const glm::vec3 n{p[0], p[1], p[2]};
  GraphBox b = c.core;
  if (!b.finite()) return "its child must be bounded";
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 q = corner(c.core, k);
    const glm::vec3 r = q - 2.0f * (glm::dot(q, n) + p[3]) * n;
    b.min = glm::min(b.min, r), b.max = glm::max(b.max, r);
  }
  out.core = b;
  out.slack = c.slack;
  return {};
}

std::string symmetry(N c, float* p, GraphNode& out) {
  out.core = c.core;
  for (int i = 0; i < 3; ++i)
    if (p[i] != 0.0f) {
      if (p[i] != 1.0f) return "'axes' must hold 0 (keep) or 1 (mirror) per axis";
      const float m = std::max(std::fabs(c.core.min[i]), std::fabs(c.core.max[i]));
      out.core.min[i] = -m, out.core.max[i] = m;
    }
  out.slack = c.slack;
  return {};
}

std::string grow(N c, float* p, GraphNode& out) {
  out.core = c.core;
  out.slack = c.slack + p[0];
  return {};
}
std::string keep(N c, float*, GraphNode& out) {
  out.core = c.core;
  out.slack = c.slack;
  return {};
}
std::string shell(N c, float* p, GraphNode& out) {
  out.core = c.core;
  out.slack = c.slack + 0.5f * p[0];
  return {};
}
std::string onion(N c, float* p, GraphNode& out) {
  out.core = c.core;
  out.slack = c.slack + p[0];
  return {};
}

std::string extrude(N c, float* p, GraphNode& out) {
  if (p[1] > 0.5f * p[0]) return "'r' must be at most h / 2";
  out.core = c.core;
  out.core.min.z = -0.5f * p[0], out.core.max.z = 0.5f * p[0];
  out.slack = c.slack;
  return {};
}
std::string extrude_half(N c, float* p, GraphNode& out) {
  out.core = c.core;
  out.core.min.z = -p[0], out.core.max.z = p[0];
  out.slack = c.slack;
  return {};
}

std::string revolve(N c, float* p, GraphNode& out) {
  const GraphBox b = full(c);
  if (!b.finite()) return "its profile must be bounded";
  const float r = std::max(0.0f, std::max(std::fabs(b.min.x + p[0]), std::fabs(b.max.x + p[0])));
  out.core = {{-r, b.min.y, -r}, {r, b.max.y, r}};
  out.slack = 0.0f;
  return {};
}

const std::vector<GraphUnary>& unaries() {
  auto floor = [](std::vector<GraphParam> v) {
    for (const char* n : {"lo", "hi"}) v.push_back(derived(n, 3));
    return v;
  };
  auto copies = [](std::vector<GraphParam> v) {
    v.push_back(derived("lo", 3));
    v.push_back(derived("hi", 3));
    v.push_back(derived("slack"));
    return v;
  };
  constexpr auto kPoint = GraphUnary::Inside::point, kCopies = GraphUnary::Inside::copies;
  static const std::vector<GraphUnary> v = {
      {"twist", floor({any("k"), axis("axis", 0, 1, 0), derived("r"), derived("l")}), 3, false, false,
       "domTwistNode", "opTwistNode", true, "bound", twist},
      {"bend", floor({any("k"), derived("r"), derived("l")}), 3, false, false, "domBendNode", "opBendNode", true,
       "bound", bend},
      {"elongate", {len("h", 3)}, 3, true, false, "domElongate", "", true, "exact outside", elongate, kPoint},
      {"repeat", copies({len("spacing", 3), counts("count")}), 3, true, true, "domRepeatNode", "", true, "exact",
       repeat, kCopies},
      {"polar", copies({any("count"), len("radius"), axis("axis", 0, 1, 0), derived("across", 3)}), 3, false, true,
       "domPolarNode", "", true, "exact", polar},
      {"mirror", {axis("n", 1, 0, 0), any("w")}, 3, true, false, "domReflect", "", true,
       "exact for a child on the kept side", mirror, kPoint},
      {"symmetry", {any("axes", 3)}, 3, true, false, "domSymmetryNode", "", true,
       "exact for a child on the positive side", symmetry, kPoint},
      {"scale", floor({len("s", 3), derived("m")}), 3, false, false, "domScaleNode", "opScaleNode", true,
       "bound (under by up to max(s) / min(s))", scale},
      {"round", {len("r")}, 3, true, false, "", "opRound", false, "exact outside", grow, kPoint},
      {"dilate", {len("r")}, 3, true, false, "", "opRound", false, "exact outside", grow, kPoint},
      {"opRound", {len("r")}, 3, true, false, "", "opRound", false, "exact outside", grow, kPoint},
      {"erode", {len("r")}, 3, true, false, "", "opErode", false, "exact inside", keep, kPoint},
      {"shell", {len("thickness")}, 3, true, false, "", "opShellNode", true, "exact outside", shell, kPoint},
      {"onion", {len("t")}, 3, true, false, "", "opOnion", false, "exact outside", onion, kPoint},
      {"opOnion", {len("t")}, 3, true, false, "", "opOnion", false, "exact outside", onion, kPoint},
      {"extrude", {len("h"), [] { GraphParam r = len("r"); r.optional = true; return r; }()}, 2, false, false, "",
       "opExtrudeNode", true, "exact", extrude, kPoint},
      {"opExtrude", {len("h")}, 2, false, false, "", "opExtrudeHalfNode", true, "exact", extrude_half, kPoint},
      {"revolve", {any("offset")}, 2, false, false, "domRevolveNode", "", true, "exact", revolve, kPoint},
  };
  return v;
}

}  // namespace

std::span<const GraphUnary> graph_unaries() { return unaries(); }
int find_unary(std::string_view name) {
  const auto& v = unaries();
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace ms
