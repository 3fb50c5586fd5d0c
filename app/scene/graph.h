// A scene as a CSG graph the program can analyse (docs/scene-graph.md):
// primitives and combinators of the shader library, one-child modifiers
// (scene/graph_unary.h), transforms folded into the leaves (or into the
// modifier above them, each of which starts a frame of its own), and per
// node a box and a Lipschitz bound. Built from
// `[scene] graph = "FILE.json"` or an inline `[scene.graph]` by
// scene/graph_build.h; turned into GLSL by shader/graph_glsl.h.
//
//   const SceneGraph& g = *scene.graph;
//   const GraphNode& root = g.nodes[g.root];   // children come before parents
//   root.box, root.lipschitz                   // the scene's bounds and Lipschitz factor
#pragma once
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace ms {

// An axis-aligned box, possibly unbounded along some axes (+-infinity).
struct GraphBox {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  bool finite() const;
};

struct GraphNode {
  bool leaf = true;
  bool unary = false;         // a modifier: one child, `left`; fn indexes graph_unaries()
  int fn = 0;                 // leaves: graph_primitives()[fn]; operators: graph_operators()[fn]
  int left = -1, right = -1;  // operators: the children, earlier in SceneGraph::nodes
  int param = 0;              // first of its parameters in SceneGraph::params
  int material = 0;           // leaves: the material id
  // Leaves and modifiers: the library function (a modifier's child) sees
  // q = to_local * p + offset and its value is multiplied by `scale`: every
  // transform up to the enclosing modifier (or the world), folded.
  glm::mat3 to_local{1.0f};
  glm::vec3 offset{0.0f};
  float scale = 1.0f;
  GraphBox box;               // world space; holds the node's surface and inside
  // box = core grown by slack, where outside `core` the field is at least
  // the distance to it minus `slack` (a blend lowers it): what lets a chain
  // of 1,000 smooth unions grow its box by one blend reach, not 1,000.
  GraphBox core;
  float slack = 0.0f;
  float lipschitz = 1.0f;     // of the node's field in world space
  bool binary() const { return !leaf && !unary; }
  int line = 0;               // in the file, for messages
};

// A node's box, core and slack are in its frame: the world's, or inside a
// modifier, the modifier's child's.
struct SceneGraph {
  std::filesystem::path file;   // the .json, or the scene's .toml for an inline graph
  std::vector<GraphNode> nodes; // postfix: every operator after its children
  std::vector<float> params;    // leaves' and modifiers' in local units; operators' lengths in their frame's units
  int root = -1;
  int primitives = 0, operators = 0;
  const GraphNode& root_node() const { return nodes[static_cast<std::size_t>(root)]; }
};

// The box of a set: every world point where a node's field may be <= 0.
GraphBox box_union(const GraphBox& a, const GraphBox& b);
GraphBox box_intersection(const GraphBox& a, const GraphBox& b);
GraphBox box_grow(const GraphBox& a, float by);

}  // namespace ms
