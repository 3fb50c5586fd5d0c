// A scene graph evaluated by a small GLSL interpreter over node buffers
// (docs/scene-graph.md), so that compile time stays flat however many
// nodes there are, and the pruning pass (render/graph_field.h) that keeps
// per grid cell only the nodes that can change the field there.
//
//   GraphEvalPlan plan = plan_graph_eval(g, GraphEval::auto_, true, bounds);
//   GraphBuffers b = graph_buffers(g);              // uploaded by render/graph_field.h
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
inline constexpr int kInterpretFrom = 512;

// One level of the pruning grid: level 0 covers the region rays march,
// each next one a larger box around it (for the shadows, AO taps and
// reflections that leave it); a point takes the finest level holding it.
struct GridLevel {
  glm::vec3 min{0.0f};   // the corner
  glm::vec3 cell{0.0f};  // one cell's size
  glm::ivec3 dims{0};    // cells along x, y, z
};
inline constexpr int kGridLevels = 3;
struct GraphEvalPlan {
  bool interpret = false;
  bool prune = false;            // the interpreter with a grid of cell lists
  bool keep_all = false;         // --no-prune: every cell's list is the whole program
  // The pruning pass runs: a grid whose cells get pruned lists.
  bool pruned() const { return prune && !keep_all; }
  GridLevel levels[kGridLevels];
  GraphBox surfaces;             // the graph's box: past the last level map() is the distance to it
  int list_max = 0;              // a fine cell's list holds at most this many instructions, else its coarse cell's
  std::size_t pool = 0;          // instructions all fine cells' lists may take together
};
// `box`: the region rays march (the scene's bounds); level 0 covers it.
// `cell_size` > 0 sets level 0's cells, else they follow the node count.
GraphEvalPlan plan_graph_eval(const SceneGraph& g, GraphEval eval, bool prune, const GraphBox& box,
                              float cell_size = 0.0f);
// The node buffers the interpreter reads (binding points in graph_interp.cpp).
struct GraphBuffers {
  std::vector<std::uint32_t> nodes;  // 4 per node: fn, float offset, material (a modifier: its unit's length), Lipschitz bound's bits
  std::vector<float> floats;         // leaves and modifiers: to_local rows, offset, scale, then parameters; operators: parameters
  std::vector<std::uint32_t> program;  // postfix, the deeper child first (Sethi-Ullman): the least stack
  int stack = 0;                     // the stack the program needs
  int frames = 0;                    // the deepest nesting of modifiers
};
GraphBuffers graph_buffers(const SceneGraph& g);
int grid_split();                                          // a coarse cell's fine cells along each axis
std::size_t cell_count(const GridLevel& level);            // one level's fine cells
glm::ivec3 coarse_dims(const GridLevel& level);            // its coarse cells (kSplit^3 fine ones each) along x, y, z
std::size_t cell_count(const GraphEvalPlan& plan);         // fine cells of every level: the tracer's
std::size_t coarse_cell_count(const GraphEvalPlan& plan);  // the pruning pass's first level
// Instructions the program buffer holds: the program, the coarse cells'
// lists, then the pool of the fine cells' lists.
std::size_t program_capacity(const GraphEvalPlan& plan, const GraphBuffers& b);
// Where the fine lists' pool starts in the program buffer, in words: after
// the program and the coarse cells' lists (a pruned plan's).
std::size_t pool_base(const GraphEvalPlan& plan, const GraphBuffers& b);
// The cell buffer's head: the levels' geometry, where their cells and
// lists start, and the graph's box, so that moving the graph changes
// buffers only, never the shader. The cells follow it.
std::vector<std::uint32_t> grid_header(const GraphEvalPlan& plan, const GraphBuffers& b);
// map() interpreting the buffers, with the cell lookup when plan.prune.
std::string graph_map_interpreter(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b);
// The pruning pass's compute shader body (after the library's includes).
std::string graph_prune_source(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b);

}  // namespace ms
