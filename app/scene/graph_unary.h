// The scene graph's one-child nodes (docs/scene-graph.md, "Modifiers"): a
// point map run before the child (twist, bend, elongate, mirror, symmetry,
// non-uniform scale, revolve), a field map run after it (round, erode,
// shell, extrude), or copies of the child (repeat, polar). A node starts a
// frame of its own: its child's transforms fold up to it, not to the
// world, and its child's box and Lipschitz bound, in that frame, give its
// own (shape()). The GLSL is sdf_shaders/modifiers.glsl, checked by
// tests/library like the rest of the library.
//
//   const GraphUnary* u = &graph_unaries()[find_unary("twist")];
//   u->begin == "domTwistNode"; u->shape(child, params, node) fills the rest
#pragma once
#include <span>
#include <string_view>
#include <vector>

#include "scene/graph.h"
#include "scene/graph_vocab.h"

namespace ms {

struct GraphUnary {
  std::string_view name;
  std::vector<GraphParam> params;  // read ones, then derived ones (filled by shape())
  int child_dims = 3;              // 2: extrude and revolve take a profile
  bool on_profiles = false;        // may also sit inside a profile (2D)
  bool copies = false;             // repeat, polar: the child is run once per copy looked at
  // GLSL functions of modifiers.glsl (or the library): begin(p, params...)
  // gives the child's point, end(d, p, params...) the node's value from the
  // child's; empty: the identity.
  std::string_view begin, end;
  bool end_point = true;           // end takes p (a library op like opRound takes d and params only)
  std::string_view exactness;      // as docs/scene-graph.md's table says it
  // Fills the derived parameters and, in the node's frame, out.core,
  // out.slack and out.lipschitz (a factor on the child's). Returns an
  // empty string, or why the child cannot be used (an unbounded one).
  std::string (*shape)(const GraphNode& child, float* params, GraphNode& out) = nullptr;
  // How the pruning pass looks inside it (graph_prune.glsl). whole: kept or
  // dropped as one unit. point: its point map moves no two points farther
  // apart, so the points of a ball about c go within the same radius of
  // the map of c, and its child is pruned for that ball. copies: the child
  // is pruned for the box every copy's point of the ball lies in (repeat).
  enum class Inside { whole, point, copies };
  Inside inside = Inside::whole;
};

std::span<const GraphUnary> graph_unaries();
int find_unary(std::string_view name);  // or -1

// The copies' derived parameters end with the child's core box and slack
// (lo 3, hi 3, slack 1): the GLSL skips a copy farther than the nearest
// value so far (msCopyFloor).
inline constexpr int kCopyFloorFloats = 7;

// The most copies a repetition's point may look at (each is a loop
// iteration of the child), and the deepest nesting of modifiers (each a
// frame of the interpreter's stack, a GLSL function inline).
inline constexpr int kMaxCopies = 1024;
inline constexpr int kMaxModifierDepth = 64;

}  // namespace ms
