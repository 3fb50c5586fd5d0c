// An animation as an image sequence (docs/animation.md): one GL context
// and one compiled program for every frame, each frame at time
// frame / fps exactly. Resumable (complete frames with this run's
// fingerprint are skipped, pipeline/sequence_state.h), shardable across
// processes, with writing overlapped with rendering (io/frame_writer.h)
// and, at the end, an optional video (io/video.h).
//
//   SequenceJob job;  job.frame = ...;  job.range = {0, 59};
//   job.pattern = FramePattern("out/f_%04d.png");
//   const int code = render_sequence(job);  // 0, or 130/143 when interrupted
#pragma once
#include "pipeline/frame_job.h"

namespace ms {

// Checks, loads and assembles before the context exists (bad input throws
// ms::Error and leaves no file), then draws and writes this shard's frames.
// Returns 0, or 128 + the signal when SIGINT or SIGTERM stopped it: the
// frames rendered so far are written, and a rerun resumes.
int render_sequence(const SequenceJob& job);

}  // namespace ms
