// A graph scene's node buffers on the GPU, and the pruning pass that fills
// its grid of cells (docs/scene-graph.md): per cell, the instructions of
// the nodes that can change the field there, exactly. Built on the GPU
// when the graph is loaded, coarse cells first, its time measured.
//
//   GraphField field(*opts.graph);   // the prepared shape (shader/assemble.h); prunes it
//   field.bind();              // before each draw: binding points 3-7, as map() reads them
//   field.build_ms();          // the pruning pass's time (or the cache's read)
//   field.mean_list();         // instructions a cell keeps, on average
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/gl.h"

#include "render/program.h"
#include "shader/assemble.h"
#include "shader/graph_interp.h"
#include "shader/graph_repose.h"

namespace ms {

class GraphField {
 public:
  // The one way a graph's field is made: from its prepared shape. `prune`,
  // its pruning pass already compiled (the viewer keeps one across
  // reloads); null: compiled here when the plan prunes. `disk_cache`: a
  // pass that took long is kept on disk under a key of everything it was
  // made from, and read back next time (render/graph_field_cache.h);
  // false: always run the pass.
  explicit GraphField(const GraphParts& parts, std::shared_ptr<const Program> prune = nullptr,
                      bool disk_cache = false);
  ~GraphField();
  GraphField(const GraphField&) = delete;
  GraphField& operator=(const GraphField&) = delete;

  void bind() const;
  // The same graph at another pose (an animated graph's next frame):
  // uploads `next`'s node buffers and prunes again only the coarse cells
  // where a moved node may change the field (shader/graph_repose.h), or
  // every cell where that cannot be told; compiles nothing. False, with
  // nothing changed, when `next` needs a field of its own (another plan or
  // program).
  bool repose(const GraphParts& next);
  // Fine cells the last pruning pass pruned (all of them but after a
  // repose), of how many.
  std::size_t pruned_cells() const { return pruned_cells_; }
  std::size_t cells() const;
  double build_ms() const { return build_ms_; }
  bool from_cache() const { return from_cache_; }
  // "grid 16x23x22, pruning 412.3 ms, mean list 23.4 instructions (of 1999), 3 cells kept their coarse list",
  // then why a cache entry that was there was not used, if one was not; "" without a grid.
  std::string summary() const;
  // The pruning pass's program; null when the plan does not prune.
  const std::shared_ptr<const Program>& prune() const { return prune_; }

 private:
  void run_pass(const Program& prune, const ReposeCells* only = nullptr);
  void measure();
  GLuint buffers_[6] = {0, 0, 0, 0, 0, 0};  // nodes, floats, program and lists, cells, coarse cells, cells to repose
  GraphParts parts_;  // the shape at the pose the lists are for
  std::size_t pruned_cells_ = 0;
  double build_ms_ = 0.0;
  bool from_cache_ = false;
  // Over the fine cells: the mean list length (a cell that would overflow
  // keeps its coarse cell's list), -1 before a pruning pass; and how many overflowed.
  double mean_list_ = -1.0;
  int overflowed_ = 0;
  int overflowed_whole_ = 0;  // after the last pass over every cell
  // The fine cells as the last pass left them (measure() reads them): a
  // repose finds each one's bound here.
  std::vector<std::uint32_t> fine_;
  std::string cache_note_;  // "; the cache's entry ... not used ...", or empty
  const GraphEvalPlan& plan_ = parts_.plan;
  std::size_t program_ = 0;
  std::shared_ptr<const Program> prune_;
};

}  // namespace ms
