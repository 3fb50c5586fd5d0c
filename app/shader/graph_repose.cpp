#include "shader/graph_repose.h"

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "scene/graph_vocab.h"
#include "shader/graph_interp_detail.h"

namespace ms {

namespace {

// The floats of node i: from its offset to the next node's (the buffer's end for the last).
std::pair<std::size_t, std::size_t> float_range(const GraphBuffers& b, std::size_t i) {
  const std::size_t n = b.nodes.size() / 4;
  return {b.nodes[4 * i + 1], i + 1 < n ? b.nodes[4 * (i + 1) + 1] : b.floats.size()};
}

}  // namespace

bool same_grid(const GraphEvalPlan& a, const GraphEvalPlan& b) {
  if (a.prune != b.prune || a.keep_all != b.keep_all || a.list_max != b.list_max || a.pool != b.pool) return false;
  for (int l = 0; l < kGridLevels; ++l)
    if (a.levels[l].min != b.levels[l].min || a.levels[l].cell != b.levels[l].cell || a.levels[l].dims != b.levels[l].dims)
      return false;
  return true;
}

namespace {

// The margin a moved node's value must keep above the field for it to
// change nothing: 1.25 times the blend radii of its ancestors, or -1 when
// one of them is not a plain or quadratic smooth union.
float union_margin(const SceneGraph& g, const std::vector<int>& parent, int i) {
  float margin = 0.0f;
  for (int p = parent[static_cast<std::size_t>(i)]; p != -1; p = parent[static_cast<std::size_t>(p)]) {
    const GraphNode& n = g.nodes[static_cast<std::size_t>(p)];
    if (!n.binary()) return -1.0f;
    const std::string_view op = graph_operators()[static_cast<std::size_t>(n.fn)].name;
    if (op == "opSmoothUnion") margin += 1.25f * g.params[static_cast<std::size_t>(n.param)];
    else if (op != "opUnion") return -1.0f;
  }
  return margin;
}

// Least distance from a ball to a box, 0 where they meet.
float ball_to_box(glm::vec3 c, float r, const GraphBox& b) {
  const glm::vec3 d = glm::max(glm::max(b.min - c, c - b.max), glm::vec3(0.0f));
  return std::max(glm::length(d) - r, 0.0f);
}

// A moved node and what bounds its value below, before and after.
struct Moved {
  GraphBox core[2];
  float slack[2];
  float margin;
};

}  // namespace

std::size_t ReposeCells::count() const {
  std::size_t n = 0;
  for (const auto& l : fine) n += l.size();
  return n;
}

namespace {

// Whether a moved node may change the field on the ball (c, r), where the
// field is at most u: its box floor, before or after, within u plus its margin.
bool reaches(const std::vector<Moved>& moved, glm::vec3 c, float r, float u) {
  if (std::isnan(u)) return false;  // inside the finer level: never looked up
  for (const Moved& m : moved)
    for (int s = 0; s < 2; ++s) {
      const float dist = ball_to_box(c, r, m.core[s]);
      // Touching the core the value may be anything down to minus its reach.
      if (dist <= 0.0f || !(dist - m.slack[s] >= u + m.margin)) return true;
    }
  return false;
}

// The moved nodes, each with the boxes bounding its value and its margin;
// nullopt where a change cannot be bounded.
std::optional<std::vector<Moved>> moved_nodes(const GraphParts& before, const GraphParts& after) {
  const GraphBuffers &a = before.buffers, &b = after.buffers;
  const SceneGraph &ga = *before.graph, &gb = *after.graph;
  std::vector<int> parent(gb.nodes.size(), -1);
  for (std::size_t i = 0; i < gb.nodes.size(); ++i)
    for (int c : {gb.nodes[i].left, gb.nodes[i].right})
      if (c >= 0) parent[static_cast<std::size_t>(c)] = static_cast<int>(i);
  std::vector<Moved> moved;
  for (std::size_t i = 0; i < gb.nodes.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k)  // function, floats' offset, material: the structure
      if (a.nodes[4 * i + k] != b.nodes[4 * i + k]) return std::nullopt;
    const auto [lo, hi] = float_range(b, i);
    if (std::memcmp(a.floats.data() + lo, b.floats.data() + lo, (hi - lo) * sizeof(float)) == 0 &&
        a.nodes[4 * i + 3] == b.nodes[4 * i + 3])
      continue;
    const GraphNode &na = ga.nodes[i], &nb = gb.nodes[i];
    if (nb.binary()) return std::nullopt;  // an operator's parameter: its whole subtree may change anywhere
    const float margin = union_margin(gb, parent, static_cast<int>(i));
    if (margin < 0.0f) return std::nullopt;
    moved.push_back({{na.core, nb.core}, {na.slack, nb.slack}, margin});
  }
  return moved;
}

}  // namespace

std::optional<ReposeCells> repose_cells(const GraphParts& before, const GraphParts& after, const GridUpper& upper) {
  const GraphBuffers &a = before.buffers, &b = after.buffers;
  if (!before.graph || !after.graph || !same_grid(before.plan, after.plan) || !after.plan.pruned() ||
      a.program != b.program || a.nodes.size() != b.nodes.size() || a.floats.size() != b.floats.size() ||
      upper.coarse.size() != coarse_cell_count(after.plan) || upper.fine.size() != cell_count(after.plan) ||
      upper.fine_far.size() != upper.fine.size() || before.graph->nodes.size() != after.graph->nodes.size() ||
      after.graph->nodes.size() * 4 != b.nodes.size())
    return std::nullopt;
  const std::optional<std::vector<Moved>> moved = moved_nodes(before, after);
  if (!moved) return std::nullopt;
  ReposeCells out;
  std::size_t coarse_at = 0, fine_at = 0;
  const int split = graph_detail::kSplit;
  for (int l = 0; l < kGridLevels; ++l) {
    const GridLevel& level = after.plan.levels[l];
    const glm::ivec3 d = coarse_dims(level), fd = level.dims;
    // As the pass's own radii (graph_prune.glsl), a little over.
    const float rc = 0.5f * glm::length(level.cell * float(split)) * 1.001f + 1e-6f;
    const float rf = 0.5f * glm::length(level.cell) * 1.001f + 1e-6f;
    std::vector<std::uint8_t> dirty(static_cast<std::size_t>(d.x) * d.y * d.z, 0);
    for (int z = 0, i = 0; z < d.z; ++z)
      for (int y = 0; y < d.y; ++y)
        for (int x = 0; x < d.x; ++x, ++i) {
          const glm::vec3 c = level.min + (glm::vec3(x, y, z) + 0.5f) * level.cell * float(split);
          dirty[static_cast<std::size_t>(i)] = reaches(*moved, c, rc, upper.coarse[coarse_at + static_cast<std::size_t>(i)]);
          if (dirty[static_cast<std::size_t>(i)]) out.coarse[static_cast<std::size_t>(l)].push_back(static_cast<std::uint32_t>(i));
        }
    for (int z = 0, i = 0; z < fd.z; ++z)
      for (int y = 0; y < fd.y; ++y)
        for (int x = 0; x < fd.x; ++x, ++i) {
          const std::size_t at = fine_at + static_cast<std::size_t>(i);
          const std::size_t parent = static_cast<std::size_t>(x / split + d.x * (y / split + d.y * (z / split)));
          const glm::vec3 c = level.min + (glm::vec3(x, y, z) + 0.5f) * level.cell;
          if ((upper.fine_far[at] && dirty[parent]) || reaches(*moved, c, rf, upper.fine[at]))
            out.fine[static_cast<std::size_t>(l)].push_back(static_cast<std::uint32_t>(i));
        }
    coarse_at += dirty.size();
    fine_at += cell_count(level);
  }
  return out;
}

}  // namespace ms
