// The scene graph's vocabulary: the shader library's 3D primitives and its
// two-field combinators, each with its GLSL parameters (the names after
// `p`, or after `a, b`), its Lipschitz bound as the library's comment tag
// claims it (tests/library verifies the claims; tests/unit checks this
// table against sdf_shaders/), its box and, for combinators, how far the
// blend reaches and how a child may be pruned.
//
//   const GraphPrimitive* s = find_primitive("sdSphere");
//   s->params[0].name == "r"; s->box(params) -> local box
#pragma once
#include <span>
#include <string_view>
#include <vector>

#include "scene/graph.h"

namespace ms {

struct GraphParam {
  std::string_view name;
  int size = 1;          // floats: 1 (float), 2 (vec2), 3 (vec3)
  bool nonneg = true;    // a size: negative is refused (positions, directions, offsets may be)
  bool length = true;    // combinators: in length units, so scaled with the node (a count n is not)
  // A [min, max] pair (size 2) either end of which may be open (null, or
  // TOML's -inf / inf), and which may be left out (open both ways); an open
  // end is stored as -+kOpenBound.
  bool range = false;
  bool unit = false;     // a direction of unit length (within 1e-4), as the bound of L = 1 needs
  bool optional = false; // may be left out: then `fallback`
  float fallback[3] = {0.0f, 0.0f, 0.0f};
  bool derived = false;  // not read: the builder derives it from the child (graph_unary.h)
  bool fraction = false; // a weight in [0, 1]
  // A vertex list: 3 to `points` [x, y] pairs, stored as their count, then
  // the pairs, the last repeated to fill (size is 1 + 2 points).
  int points = 0;
};

// The most vertices a polygon (sd2Polygon) takes: its GLSL array's length.
inline constexpr int kPolygonPoints = 32;

// An open end of a range parameter: the library's BIG, finite so that the
// GLSL's distances to a side stay exact; a box treats it as infinite.
inline constexpr float kOpenBound = 1e20f;

struct GraphPrimitive {
  std::string_view name;
  std::vector<GraphParam> params;
  float lipschitz = 1.0f;
  GraphBox (*box)(const float* params) = nullptr;  // local space
  int dims = 3;          // 2: a profile (sd2*) of p.xy, for extrude and revolve
};

// How a combinator's value relates to its children's, for the box and for
// pruning (docs/scene-graph.md, "Pruning").
enum class OpFamily {
  union_,         // min-like: the surface is the children's, grown by reach
  intersection,   // max-like: inside both
  subtraction,    // max(a, -b)-like: inside a
  other,          // pipe, engrave, groove, tongue: a's material; b pruned by its |b|, if at all
};

struct GraphOperator {
  std::string_view name;
  std::vector<GraphParam> params;
  float lipschitz = 1.0f;  // times the children's
  OpFamily family = OpFamily::other;
  // The node's core box and slack (graph.h) from its children's and the
  // (world-unit) parameters.
  void (*box)(const GraphNode& a, const GraphNode& b, const float* params, GraphNode& out) = nullptr;
  // Pruning, a GLSL expression of a's interval on a cell (ALO, AHI) and the
  // parameters P0, P1, for which op(a, b) == a on the whole cell: for the
  // min-like families, a least lo(b) - hi(a) (for intersections and
  // subtractions, of the negated fields; the same with a and b swapped
  // drops a); for `other`, a least |b| on the cell. Empty: this node keeps
  // both children (its subtrees are still pruned).
  std::string_view reach;
};

std::span<const GraphPrimitive> graph_primitives();
std::span<const GraphOperator> graph_operators();
// Index into the spans above, or -1.
int find_primitive(std::string_view name);
int find_operator(std::string_view name);
// Parameter floats in total.
int param_floats(const std::vector<GraphParam>& params);

}  // namespace ms
