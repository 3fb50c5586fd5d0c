// Which coarse cells a new pose prunes again (shader/graph_repose.h), with
// no GL: a sphere moved inside a field of them dirties only the cells near
// its old and new places; what it cannot bound (an operator's parameter,
// a moved node under an intersection, another grid) asks for every cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "graph_of.h"
#include "scene/scene.h"
#include "shader/graph_repose.h"

namespace ms::test {
namespace {

// 100 spheres 0.3 apart in a square at y = 0 under `op`; the first at (x0, 0, z0).
std::string field(double x0, double z0, const std::string& op = "\"opUnion\"") {
  std::string kids;
  for (int i = 0; i < 100; ++i) {
    const double x = i ? -1.35 + 0.3 * (i % 10) : x0, z = i ? -1.35 + 0.3 * (i / 10) : z0;
    kids += std::string(i ? ", " : "") + R"({"sdf": "sdSphere", "r": 0.1, "translate": [)" + std::to_string(x) +
            ", 0, " + std::to_string(z) + "]}";
  }
  return R"({"root": {"op": )" + op + R"(, "children": [)" + kids + "]}}";
}

GraphParts parts_of(const std::string& json, GraphBox bounds = {{-1.6f, -0.5f, -1.6f}, {1.6f, 0.5f, 1.6f}}) {
  Scene s;
  s.graph = std::make_shared<const SceneGraph>(graph_of(json));
  s.bounds.kind = BoundsKind::box;
  s.bounds.min = bounds.min;
  s.bounds.max = bounds.max;
  AssembleOptions opts;
  opts.graph_eval = GraphEval::interpreter;
  GraphParts p;
  p.graph = s.graph;
  p.plan = plan_graph_eval(*s.graph, opts.graph_eval, true, bounds);
  p.buffers = graph_buffers(*s.graph);
  return p;
}

// Every coarse cell's field at most 0.2: what a pruning pass would keep
// for cells near the spheres (a cell farther off has a larger bound).
GridUpper upper_of(const GraphParts& p, float u = 0.2f) {
  GridUpper g;
  g.coarse.assign(coarse_cell_count(p.plan), u);
  g.fine.assign(cell_count(p.plan), u);
  g.fine_far.assign(cell_count(p.plan), 0);
  return g;
}

TEST(GraphRepose, AMovedSphereDirtiesOnlyTheCellsNearItsOldAndNewPlace) {
  const GraphParts a = parts_of(field(-1.35, -1.35)), b = parts_of(field(-1.25, -1.35));
  const std::optional<ReposeCells> d = repose_cells(a, b, upper_of(a));
  ASSERT_TRUE(d.has_value());
  EXPECT_GT(d->count(), 0u);
  EXPECT_LE(10 * d->count(), cell_count(a.plan));
  std::size_t coarse = 0;
  for (const auto& l : d->coarse) coarse += l.size();
  EXPECT_GT(coarse, 0u);
  EXPECT_LE(10 * coarse, coarse_cell_count(a.plan));
  // Nothing moved: nothing to prune again.
  EXPECT_EQ(repose_cells(a, a, upper_of(a))->count(), 0u);
  // A cell whose field may be large is reached from farther off.
  EXPECT_GT(repose_cells(a, b, upper_of(a, 2.0f))->count(), d->count());
  // A cell inside the finer level (NaN) is never pruned.
  GridUpper none = upper_of(a, std::nanf(""));
  EXPECT_EQ(repose_cells(a, b, none)->count(), 0u);
  // A far cell holding its coarse cell's bound goes with that cell.
  GridUpper far = upper_of(a);
  far.fine.assign(far.fine.size(), std::nanf(""));
  far.fine_far.assign(far.fine.size(), 1);
  const ReposeCells f = *repose_cells(a, b, far);
  std::size_t expected = 0;
  for (int l = 0; l < kGridLevels; ++l) {
    const GridLevel& g = a.plan.levels[l];
    const glm::ivec3 cd = coarse_dims(g);
    const std::vector<std::uint32_t>& dirty = f.coarse[static_cast<std::size_t>(l)];
    for (int i = 0; i < g.dims.x * g.dims.y * g.dims.z; ++i) {
      const glm::ivec3 c(i % g.dims.x, (i / g.dims.x) % g.dims.y, i / (g.dims.x * g.dims.y));
      const glm::ivec3 p = c / grid_split();
      const auto parent = static_cast<std::uint32_t>(p.x + cd.x * (p.y + cd.y * p.z));
      expected += std::find(dirty.begin(), dirty.end(), parent) != dirty.end();
    }
  }
  EXPECT_GT(expected, 0u);
  EXPECT_EQ(f.count(), expected);
}

TEST(GraphRepose, BlendsWidenTheReach) {
  const std::string smooth = R"("opSmoothUnion", "k": 0.3)";
  const GraphParts a = parts_of(field(-1.35, -1.35)), b = parts_of(field(-1.25, -1.35));
  const GraphParts sa = parts_of(field(-1.35, -1.35, smooth)), sb = parts_of(field(-1.25, -1.35, smooth));
  EXPECT_GT(repose_cells(sa, sb, upper_of(sa))->count(), repose_cells(a, b, upper_of(a))->count());
}

TEST(GraphRepose, WhatItCannotBoundPrunesEveryCell) {
  const GraphParts a = parts_of(field(-1.35, -1.35));
  // Under an intersection a moved node may cut anything.
  const std::string inter = R"({"root": {"op": "opIntersection", "children": [{"sdf": "sdBox", "b": [2, 2, 2]}, )";
  const std::string f0 = field(-1.35, -1.35), f1 = field(-1.25, -1.35);
  const GraphParts ia = parts_of(inter + f0.substr(9, f0.size() - 10) + "]}}");
  const GraphParts ib = parts_of(inter + f1.substr(9, f1.size() - 10) + "]}}");
  EXPECT_FALSE(repose_cells(ia, ib, upper_of(ia)).has_value());
  // A blend radius changes the field wherever the blend is.
  const GraphParts sa = parts_of(field(-1.35, -1.35, R"("opSmoothUnion", "k": 0.3)"));
  const GraphParts sb = parts_of(field(-1.35, -1.35, R"("opSmoothUnion", "k": 0.2)"));
  EXPECT_FALSE(repose_cells(sa, sb, upper_of(sa)).has_value());
  // Another grid, or a count of bounds that is not the grid's.
  const GraphParts moved = parts_of(field(-1.25, -1.35), {{-1.7f, -0.5f, -1.6f}, {1.6f, 0.5f, 1.6f}});
  EXPECT_FALSE(repose_cells(a, moved, upper_of(a)).has_value());
  GridUpper short_ = upper_of(a);
  short_.coarse.resize(3);
  EXPECT_FALSE(repose_cells(a, a, short_).has_value());
}

}  // namespace
}  // namespace ms::test
