// A pruned grid kept on disk (io/cache_dir.h, `pruned/`): the pruning pass
// of a large graph takes seconds on llvmpipe, and the same scene is drawn
// again and again (a batch's jobs, a test suite's cases, a mesh after a
// render). The key hashes everything the grid is made from: the graph's
// buffers, the plan's grid header, the pruning shader's text and the GL
// renderer and version; an entry of any other size is a miss.
//
//   PrunedCache c(buffers, plan, prune_source);   // no key when the source is empty
//   if (c.load(bufs, sizes)) ...;                  // the three buffers filled
//   c.save(bufs, sizes);                           // after a pass that took long enough
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>

#include "gl/gl.h"
#include "shader/graph_interp.h"

namespace ms {

// Worth keeping: a pass that took at least this long (a small graph's
// pass is quicker than reading its entry back): 300 ms, or
// $MARCH_PRUNE_CACHE_MS (tests keep every pass of a small graph with 0).
double prune_cache_ms();

class PrunedCache {
 public:
  PrunedCache(const GraphBuffers& b, const GraphEvalPlan& plan, const std::string& prune_source);
  // Fills buffers (program and lists, cells, coarse cells) of exactly
  // `bytes` each from the entry; false on a miss. Of the first only the
  // part in use is kept: up to `pool_base` bytes and the pool's words
  // taken (the coarse buffer's first word counts them).
  bool load(const GLuint buffers[3], const std::size_t bytes[3]) const;
  void save(const GLuint buffers[3], const std::size_t bytes[3], std::size_t pool_base) const;

 private:
  std::filesystem::path path_;  // empty: no cache
};

}  // namespace ms
