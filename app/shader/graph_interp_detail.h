// Pieces the interpreter (graph_interp.cpp), its grid (graph_grid.cpp) and
// the pruning pass (graph_prune.cpp) share; not for use outside shader/.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scene/graph_vocab.h"
#include "shader/graph_interp.h"

namespace ms::graph_detail {

// The pruning pass's two levels: coarse cells of kSplit^3 fine ones, each
// keeping up to kCoarseList instructions.
inline constexpr int kSplit = 4;
inline constexpr std::size_t kCoarseList = 2048;
// The cell buffer's head, in uvec4s: one for the list pool, three a grid
// level, two for the graph's box (grid_header()).
inline constexpr int kHeader = 3 + 3 * kGridLevels;

// msGraphPrim and msGraphOp: a case for each function the graph uses.
std::string dispatch_glsl(const SceneGraph& g);
// Parameters read from the float buffer at o, as GLSL arguments (", a, vec3(b...)").
std::string buffer_args(const std::vector<GraphParam>& params);
// The defines sdf_shaders/graph_interp.glsl reads; `copies` of its loop body.
std::string defines(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b, int copies);

}  // namespace ms::graph_detail
