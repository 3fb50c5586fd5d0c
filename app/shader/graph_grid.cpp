// The pruning grid's plan and the head of its cell buffer.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "shader/graph_interp_detail.h"

namespace ms {

using graph_detail::kCoarseList;

namespace {

// A coarse cell walks the whole program in one loop, which llvmpipe would
// cut short past 65,535 iterations (graph_interp.cpp).
constexpr int kPruneLoopLimit = 65000;
// All fine lists together, in instructions (64 MiB); past it a cell keeps
// its coarse cell's list, which is as exact and only longer.
constexpr std::size_t kPoolMax = std::size_t{16} << 20;

GridLevel level_over(glm::vec3 lo, glm::vec3 extent, double cells, float side) {
  extent = glm::max(extent, glm::vec3(1e-4f));
  if (side <= 0.0f) side = static_cast<float>(std::cbrt(double(extent.x) * extent.y * extent.z / cells));
  GridLevel l;
  l.dims = glm::clamp(glm::ivec3(glm::ceil(extent / side)), glm::ivec3(1), glm::ivec3(256));
  l.cell = extent / glm::vec3(l.dims);
  l.min = lo;
  return l;
}

std::uint32_t bits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

std::size_t volume_of(glm::ivec3 d) {
  return static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) * static_cast<std::size_t>(d.z);
}

}  // namespace

int grid_split() { return graph_detail::kSplit; }

glm::ivec3 coarse_dims(const GridLevel& level) { return (level.dims + graph_detail::kSplit - 1) / graph_detail::kSplit; }

std::size_t cell_count(const GridLevel& level) { return volume_of(level.dims); }

std::size_t coarse_cell_count(const GraphEvalPlan& plan) {
  std::size_t n = 0;
  for (const GridLevel& l : plan.levels) n += volume_of(coarse_dims(l));
  return n;
}

std::size_t cell_count(const GraphEvalPlan& plan) {
  std::size_t n = 0;
  for (const GridLevel& l : plan.levels) n += cell_count(l);
  return n;
}

std::size_t pool_base(const GraphEvalPlan& plan, const GraphBuffers& b) {
  return b.program.size() + coarse_cell_count(plan) * kCoarseList;
}

std::size_t program_capacity(const GraphEvalPlan& plan, const GraphBuffers& b) {
  if (!plan.pruned()) return b.program.size();
  return pool_base(plan, b) + plan.pool;
}

GraphEvalPlan plan_graph_eval(const SceneGraph& g, GraphEval eval, bool prune, const GraphBox& box, float cell_size) {
  GraphEvalPlan plan;
  plan.interpret = eval == GraphEval::interpreter || (eval == GraphEval::auto_ && g.primitives >= kInterpretFrom);
  plan.surfaces = g.root_node().box;
  plan.prune = plan.interpret && box.finite() && !box.empty() && plan.surfaces.finite() &&
               2 * g.primitives < kPruneLoopLimit;
  // --no-prune keeps the grid, each cell holding the whole program: the
  // same shader, so the reference differs from the pruned field only by
  // what pruning drops (nothing, when it is exact), not by how a compiler
  // happened to round two different programs.
  plan.keep_all = !prune;
  if (!plan.prune) return plan;
  // Level 0: about 32 fine cells a primitive, within 16^3 and 2^17, over
  // the bounds grown by a tenth of their largest half side: AO taps and
  // shadow rays start just outside the bounds, on a floor under the
  // objects, and are the most numerous map() calls there.
  const double target = std::clamp(32.0 * g.primitives, 4096.0, 131072.0);
  const glm::vec3 b_half = 0.5f * (box.max - box.min);
  const float margin = 0.1f * std::max({b_half.x, b_half.y, b_half.z});
  plan.levels[0] = level_over(box.min - margin, box.max - box.min + 2.0f * margin, target, cell_size);
  // The outer levels hold shadow rays, AO taps and reflections that leave
  // the bounds: each around the bounds and the graph, twice the last one's
  // size plus a quarter of its largest half side, in cells twice as large,
  // so a level's cells are as far from the surfaces, relative to their
  // size, as the last one's edge cells.
  const glm::vec3 lo = glm::min(box.min, plan.surfaces.min), hi = glm::max(box.max, plan.surfaces.max);
  const glm::vec3 centre = 0.5f * (hi + lo);
  glm::vec3 half = 0.5f * (hi - lo);
  const float grow = 0.25f * std::max({half.x, half.y, half.z, 1e-3f});
  float side = std::max({plan.levels[0].cell.x, plan.levels[0].cell.y, plan.levels[0].cell.z});
  for (int j = 1; j < kGridLevels; ++j) {
    half = 2.0f * half + grow;
    side *= 2.0f;
    plan.levels[j] = level_over(centre - half, 2.0f * half, 0.0, side);
  }
  plan.list_max = 256;
  plan.pool = std::min(cell_count(plan) * static_cast<std::size_t>(plan.list_max), kPoolMax);
  return plan;
}

std::vector<std::uint32_t> grid_header(const GraphEvalPlan& plan, const GraphBuffers& b) {
  std::vector<std::uint32_t> h(graph_detail::kHeader * 4, 0u);
  const std::size_t len = b.program.size();
  h[0] = static_cast<std::uint32_t>(pool_base(plan, b));
  h[1] = static_cast<std::uint32_t>(plan.pool);
  h[2] = static_cast<std::uint32_t>(len);
  std::size_t cells = 0, coarse = 0;
  for (int j = 0; j < kGridLevels; ++j) {
    const GridLevel& l = plan.levels[j];
    std::uint32_t* e = h.data() + 4 * (1 + 3 * j);
    for (int k = 0; k < 3; ++k) {
      e[k] = bits(l.min[k]);
      e[4 + k] = bits(l.cell[k]);
      e[8 + k] = static_cast<std::uint32_t>(l.dims[k]);
    }
    e[3] = static_cast<std::uint32_t>(cells);
    e[7] = static_cast<std::uint32_t>(coarse);
    cells += cell_count(l);
    coarse += volume_of(coarse_dims(l));
  }
  std::uint32_t* s = h.data() + 4 * (1 + 3 * kGridLevels);
  for (int k = 0; k < 3; ++k) {
    s[k] = bits(plan.surfaces.min[k]);
    s[4 + k] = bits(plan.surfaces.max[k]);
  }
  return h;
}

}  // namespace ms
