// A pruned grid kept on disk (io/cache_dir.h, `pruned/`): the pruning pass
// of a large graph takes seconds on llvmpipe, and the same scene is drawn
// again and again (a batch's jobs, a test suite's cases, a mesh after a
// render). The key hashes everything the grid is made from: the graph's
// buffers, the plan's grid header, the pruning shader's text and the GL
// renderer and version.
//
// An entry is a hint, never trusted as it stands: the grid decides which
// nodes a pixel evaluates, so one wrong word draws a wrong image. It is
//
//   "MSPRUNE2", the key (32 hex), u64 bytes kept of each buffer and the
//   pool's base, a content hash (32 hex) of all that and the body, the body
//
// and is used only when every header field is what this plan implies, the
// size adds up, the pool's count agrees with the first buffer's length and
// the hash matches. Anything else (or a link, a FIFO) is a miss with its
// reason; a damaged regular file is written anew after the pass.
//
//   PrunedCache c(buffers, plan, prune_source);   // no key when the source is empty
//   if (c.load(bufs, sizes, &why)) ...;            // the three buffers filled
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

// What the plan implies, in bytes: each buffer's size (program and lists,
// cells, coarse cells) and where the fine lists' pool starts in the first.
struct PrunedSizes {
  std::size_t bytes[3] = {0, 0, 0};
  std::size_t pool_base = 0;
};

class PrunedCache {
 public:
  PrunedCache(const GraphBuffers& b, const GraphEvalPlan& plan, const std::string& prune_source);
  // Fills the three buffers from the entry; false on a miss. Of the first
  // only the part in use is kept: up to the pool's base and the pool's
  // words taken (the coarse buffer's first word counts them). `refused`
  // (may be null) gets why an entry that is there was not used, and is
  // empty when there is none.
  bool load(const GLuint buffers[3], const PrunedSizes& sizes, std::string* refused = nullptr) const;
  // False when it was not written (no cache, too large, a path that is
  // not a regular file, a failed write): a hint, never an error.
  bool save(const GLuint buffers[3], const PrunedSizes& sizes) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;  // empty: no cache
};

}  // namespace ms
