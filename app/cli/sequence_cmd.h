// `marchstudio render SCENE --frames A..B`: an animation as an image
// sequence, one GL context and one compiled program for every frame, each
// frame at time frame / fps exactly. Resumable (complete frames are
// skipped), shardable across processes (--shard I/N), with writing
// overlapped with rendering. docs/animation.md describes it.
#pragma once

namespace ms {

struct RenderArgs;

// True when a sequence flag was given (--frames, --fps, --shard,
// --shard-mode, --video, --no-write): run_render hands over to run_sequence,
// which rejects them without --frames.
bool wants_sequence(const RenderArgs& a);

// Exit codes as for render, plus 130 (SIGINT) or 143 (SIGTERM) when
// interrupted: the frames rendered so far are written, and a rerun resumes.
int run_sequence(const RenderArgs& a);

}  // namespace ms
