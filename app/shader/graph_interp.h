// A scene graph evaluated by a small GLSL interpreter over node buffers
// (docs/scene-graph.md), so that compile time stays flat however many
// nodes there are, and the pruning pass (render/graph_field.h) that keeps
// per grid cell only the nodes that can change the field there.
//
//   GraphEvalPlan plan = plan_graph_eval(g, GraphEval::auto_, true, bounds);
//   GraphBuffers b = graph_buffers(g, plan);        // uploaded by render/graph_field.h
//   std::string glsl = graph_map_interpreter(g, plan, b);
//   std::string prune = graph_prune_source(g, plan, b);  // the pruning compute pass's map part
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/graph.h"

namespace ms {

enum class GraphEval { auto_, inline_, interpreter };

// At or above this many primitives `auto` interprets (docs/scene-graph.md
// gives the measured crossover).
inline constexpr int kInterpretFrom = 64;

struct GraphEvalPlan {
  bool interpret = false;
  bool prune = false;            // the interpreter with a grid of cell lists
  bool keep_all = false;         // --no-prune: every cell's list is the whole program
  glm::ivec3 dims{0};            // cells along x, y, z
  glm::vec3 min{0.0f};           // the grid's corner
  glm::vec3 cell{0.0f};          // one cell's size
  int list_max = 0;              // a cell's list holds at most this many instructions, else the whole program
};

// `box`: the region rays march (the scene's bounds); the grid covers it.
// `cell_size` > 0 sets the cells' size, else it follows the node count.
GraphEvalPlan plan_graph_eval(const SceneGraph& g, GraphEval eval, bool prune, const GraphBox& box,
                              float cell_size = 0.0f);

// The node buffers the interpreter reads (binding points in graph_interp.cpp).
struct GraphBuffers {
  std::vector<std::uint32_t> nodes;  // 4 per node: fn, float offset, material, Lipschitz bound's bits
  std::vector<float> floats;         // leaves: to_local rows, offset, scale, then parameters; operators: parameters
  std::vector<std::uint32_t> program;  // postfix, the deeper child first (Sethi-Ullman): the least stack
  int stack = 0;                     // the stack the program needs
};
GraphBuffers graph_buffers(const SceneGraph& g, const GraphEvalPlan& plan);
std::size_t cell_count(const GraphEvalPlan& plan);         // fine cells: the tracer's
std::size_t coarse_cell_count(const GraphEvalPlan& plan);  // the pruning pass's first level
// Instructions the program buffer holds: the program, then every cell's list.
std::size_t program_capacity(const GraphEvalPlan& plan, const GraphBuffers& b);

// map() interpreting the buffers, with the cell lookup when plan.prune.
std::string graph_map_interpreter(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b);
// The pruning pass's compute shader body (after the library's includes).
std::string graph_prune_source(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b);

}  // namespace ms
