// Which of a pruned grid's coarse cells a new pose of the same graph must
// prune again (docs/scene-graph.md, "Animation"): those where a moved node
// may change the field. A cell far from a moved node's old and new boxes
// keeps its lists, and they stay exact.
//
//   std::optional<ReposeCells> d = repose_cells(before, after, upper);
//   if (!d) ...                      // prune every cell: another plan, or a move it cannot bound
//   d->coarse[level], d->fine[level] // the cells to prune again, per grid level
//
// Why that is exact: under plain and quadratic smooth unions only, a
// branch whose value is at least the field's plus 1.25 times the sum of
// the blend radii above it never changes the field (each blend lowers a
// minimum by at most a quarter of its radius, and is the minimum exactly
// once its children are a radius apart). So on a cell whose field is at
// most `upper` (the root's interval there, kept by the pruning pass), a
// moved node whose box floor lies past upper + that margin, before and
// after the move, changes neither the field nor what the cell's list
// gives: its old list, run on the new buffers, is still the field.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "shader/assemble.h"

namespace ms {

struct ReposeCells {
  // Per grid level, the coarse cells and the fine cells to prune again
  // (indices within the level).
  std::array<std::vector<std::uint32_t>, kGridLevels> coarse, fine;
  std::size_t count() const;  // fine cells
};

// What the last pruning pass left in the grid: per cell of every level, in
// order, the field's upper bound on it (NaN for a cell inside the finer
// level, never looked up), and per fine cell whether it holds its coarse
// cell's lower bound in place of a list (an outer level's far cell).
struct GridUpper {
  std::vector<float> coarse, fine;
  std::vector<std::uint8_t> fine_far;
};

// The same grid: a new pose's lists can replace some of the old ones.
bool same_grid(const GraphEvalPlan& a, const GraphEvalPlan& b);

// nullopt: the whole grid must be pruned again (another plan, program or
// operator parameter, or a moved node under anything but unions). A fine
// cell is pruned again where the moved nodes may reach it, or where it
// holds the bound of a coarse cell they may reach.
std::optional<ReposeCells> repose_cells(const GraphParts& before, const GraphParts& after, const GridUpper& upper);

}  // namespace ms
