// --dispatch auto (issue 18): the faster of the fragment pass and the
// compute dispatch on this device, measured once and kept. The first use on
// a device draws the job's own scene small (kProbeWidth x kProbeHeight, its
// passes, post and bloom as the job's), a warm-up frame and kProbeFrames
// timed frames each way, glFinish around each (wall clock: the GPU timer
// reads 0 on some drivers), and keeps the faster by median in
// cache_dir()/dispatch, one line per device: GL_RENDERER, GL_VERSION and
// the choice, tab-separated, written atomically. A line that does not
// parse makes the file unreadable: ignored and rewritten, never fatal.
// An input the compute dispatch cannot run (compute_source refuses it)
// gets the fragment pass without a probe.
//
//   const Dispatch d = choose_dispatch(requested, graph, post, probe_frame, ctx, group, verbose);
//   SceneDrawer drawer(ctx, graph, d, group);
#pragma once
#include <filesystem>
#include <string>

#include "gl/context.h"
#include "render/compute_frame.h"
#include "render/graph.h"
#include "render/still.h"

namespace ms {

constexpr int kProbeWidth = 256, kProbeHeight = 144, kProbeFrames = 3;

std::filesystem::path dispatch_cache_path();

// `requested` unless it is automatic: then the cached or measured choice
// for ctx's device. `frame` is the job's frame (size and samples are the
// probe's own). A stateful graph is reset after the probe. -v (`verbose`)
// prints the choice and where it came from, on stderr:
//   marchstudio: dispatch auto: compute (cached for llvmpipe (...))
//   marchstudio: dispatch auto: probe: fragment 12.1 ms, compute 9.8 ms a frame at 256x144: compute, cached in ...
Dispatch choose_dispatch(Dispatch requested, PassGraph& graph, const Program& post, const StillFrame& frame,
                         const Context& ctx, ComputeGroup group, bool verbose);

}  // namespace ms
