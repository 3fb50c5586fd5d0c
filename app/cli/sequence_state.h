// Sequences of a shader with buffers: frame f follows from frame f-1, so
// the frames render in order, the buffers carried from one to the next,
// and each written frame takes a checkpoint of them along
// (io/checkpoint.h). A rerun resumes after the last frame that has both
// its image and its checkpoint, bit for bit as an uninterrupted run; a run
// that starts past frame 0 (a chunk shard) first replays the frames before
// its own, buffers only. Stride shards are refused: every shard would
// replay nearly all frames.
#pragma once
#include <string>
#include <vector>

#include "io/checkpoint.h"
#include "io/sequence.h"

namespace ms {

struct StatefulPlan {
  std::string key;        // io/checkpoint.h's state key
  int resume_from = -1;   // the frame whose checkpoint is restored; -1: none
  std::vector<int> todo;  // to render and write, ascending and contiguous
  int replay_until = 0;   // with no checkpoint: frames 0 .. replay_until-1 drawn first, buffers only
};

// `mine`: the frames of this run, ascending and contiguous. A frame counts
// as done when frame_is_complete() and its checkpoint are there.
StatefulPlan plan_stateful(const std::vector<int>& mine, const FramePattern& pattern, int width, int height,
                           const std::string& key, bool no_write);

}  // namespace ms
