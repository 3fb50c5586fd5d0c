// The frame pipeline's first half, with no GL: a job's input loaded, its
// overrides and Shadertoy options applied, the bloom decided, the post pass
// fused where it can be, and every pass assembled. Everything that can fail
// on bad input fails here, before a context exists.
//
//   PreparedFrame p = prepare(job, /*display=*/true);  // throws ms::Error
//   session.load(p);                                     // pipeline/frame_session.h
#pragma once
#include <memory>

#include "pipeline/frame_job.h"
#include "pipeline/input.h"
#include "render/frame.h"
#include "shader/assemble.h"

namespace ms {

struct PreparedFrame {
  AssembleOptions opts;  // as the passes were assembled (bloom's and probes' programs use them too)
  LoadedInput in;        // passes assembled; in.scene.bloom.enabled says whether this output blooms
  FrameParams fp;        // size, samples, AOVs, fused post and tile size; exposure and bloom per frame
  ShaderSource post_src;
  bool display = true;   // stored as 8-bit display values (PNG, JPEG, TIFF), not float (EXR)
  // A graph scene's shape, prepared once, is opts.graph: every pass above
  // was assembled from it, and FramePrograms makes the GraphField from it.
  // A long pruning pass's grid may be read from, and kept in, the disk
  // cache (render/graph_field_cache.h); bench turns it off to time the pass.
  bool keep_pruned = true;
};

// `display`: whether the output is a display format. A sequence's
// frame rate is set (in.scene.shadertoy.fps) before this when it has one.
PreparedFrame prepare(const FrameJob& job, bool display);

// The render targets a frame draws into: colour and accumulation, plus
// four with AOVs (render/frame.h).
inline int frame_targets(bool aovs) { return aovs ? 6 : 2; }

// The frame rate a still's frame number is counted at, as Shadertoy at
// 1 s has drawn 60: the job's fps (prepare() made it the scene's), else a
// shader's own, else kSceneFps. render's stills and test's cases alike.
double still_fps(const FrameJob& job, const LoadedInput& in);

// Each buffer pass's two textures: what a graph of these passes holds
// across frames on top of frame_targets().
int buffer_targets(const LoadedInput& in);

}  // namespace ms
