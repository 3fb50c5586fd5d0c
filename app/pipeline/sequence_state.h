// What a rerun of a sequence finds on disk, and what it renders again.
//
// Every frame: a frame file is kept only when it is complete and carries
// this run's fingerprint for that frame (pipeline/fingerprint.h); --force keeps
// none. Missing, broken and stale frames render again.
//
// Sequences of a shader with buffers: frame f follows from frame f-1, so
// the frames render in order, the buffers carried from one to the next,
// and each written frame takes a checkpoint of them along
// (io/checkpoint.h). A rerun resumes after the last frame that has both
// its image and a checkpoint that reads back with that frame's
// fingerprint, bit for bit as an uninterrupted run (a damaged or misplaced
// checkpoint is passed over with a warning: the run resumes from an earlier
// one or replays from frame 0, never stalls); a run
// that starts past frame 0 (a chunk shard) first replays the frames before
// its own, buffers only. Stride shards are refused: every shard would
// replay nearly all frames.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/checkpoint.h"
#include "io/sequence.h"
#include "render/graph.h"

namespace ms {

// The fingerprint frame f must carry to be kept.
using FrameFingerprint = std::function<std::string(int frame)>;

struct ResumeScan {
  std::vector<int> todo;                              // to render, ascending
  std::vector<std::pair<int, std::string>> skipped;  // complete and this run's: frame, path
  std::vector<std::pair<int, std::string>> redone;   // present but broken: frame, why
  std::vector<int> stale;                            // complete but made from other inputs or settings
  std::vector<int> unmarked;                         // complete but with no fingerprint (not ours, or older)
};

// Removes a killed run's temporaries of `mine` (saying so on stderr), then
// sorts the frames. `force`: everything is to render.
ResumeScan scan_existing(const FramePattern& pattern, const std::vector<int>& mine, int width, int height,
                         const FrameFingerprint& fingerprint, bool force);

struct StatefulPlan {
  std::string key;        // io/checkpoint.h's state key
  int resume_from = -1;   // the frame whose checkpoint is restored; -1: none
  std::vector<int> todo;  // to render and write, ascending and contiguous
  int replay_until = 0;   // with no checkpoint: frames 0 .. replay_until-1 drawn first, buffers only
  std::vector<int> candidates;  // complete frames with a checkpoint file, ascending; the last is resume_from
  BufferState state;            // resume_from's buffers, once load_resume_state() has read them
};

// `mine`: the frames of this run, ascending and contiguous. A frame counts
// as done when frame_is_complete() with its fingerprint and its checkpoint
// are there. `fresh` (no_write or --force): nothing counts as done.
StatefulPlan plan_stateful(const std::vector<int>& mine, const FramePattern& pattern, int width, int height,
                           const std::string& key, const FrameFingerprint& fingerprint, bool fresh);

// Reads the newest candidate's checkpoint that holds `buffers` at the size
// and carries its frame's fingerprint into p.state; each one that does not
// is a warning on stderr and passed over, down to none (then the frames
// replay from the start). Sets resume_from, todo and replay_until to match.
void load_resume_state(StatefulPlan& p, const std::vector<int>& mine, const FramePattern& pattern,
                       const std::vector<int>& buffers, int width, int height, const FrameFingerprint& fingerprint);

// Removes the temporaries of this run's checkpoints that a killed run left
// (io/checkpoint.h), saying so on stderr, as scan_existing() does for frames.
void remove_checkpoint_temps(const FramePattern& pattern, const std::vector<int>& mine, const std::string& key);

// The buffers a graph of `passes` carries, as PassGraph::buffers() lists
// them (A..D that some pass writes, then Cube A), known before any GL.
std::vector<int> state_buffers(const std::vector<PassSource>& passes);

}  // namespace ms
