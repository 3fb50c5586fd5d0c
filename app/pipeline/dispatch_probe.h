// --dispatch auto: the faster of the fragment pass and the
// compute dispatch on this device, and compute's work group, measured once
// and kept. The first use on a device draws the job's own scene (its
// passes, post and bloom as the job's) at the sizes and groups of
// pipeline/dispatch_plan.h's plan (256x144 first, larger while a frame is too
// short to measure; compute's other groups when it wins at 8x8), a warm-up
// frame and kProbeFrames timed frames each, glFinish around each (wall
// clock: the GPU timer reads 0 on some drivers), and keeps the fastest by
// median in cache_dir()/dispatch, one line per device: GL_RENDERER,
// GL_VERSION and the choice ("fragment", or "compute WxH"; a bare
// "compute" is 8x8), tab-separated, written atomically. A line that does
// not parse makes the file unreadable: ignored and rewritten, never fatal.
// A given --compute-group is the only group timed, and is what compute
// draws with even when the cache names another. An input the compute
// dispatch cannot run (compute_source refuses it) gets the fragment pass
// without a probe.
//
//   const DispatchChoice d = choose_dispatch(requested, graph, post, probe_frame, ctx, group, verbose);
//   SceneDrawer drawer(ctx, graph, d.dispatch, d.group);
#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "gl/context.h"
#include "render/compute_frame.h"
#include "render/graph.h"
#include "render/still.h"

namespace ms {

struct LoadedInput;

// With `d` compute, whether the input's frame pass can run as one
// (compute_source: derivatives and implicit-LOD lookups of a mipmapped
// input are refused at their file:line); buffer and Cube A passes stay
// fragment passes. Before the context: nothing is drawn or written first.
void check_compute_input(Dispatch d, const LoadedInput& in);

// cache_dir()/dispatch; empty when there is no cache (io/cache_dir.h).
std::filesystem::path dispatch_cache_path();

// `requested` (with `group`, or 8x8) unless it is automatic: then the
// cached or measured choice for ctx's device. `frame` is the job's frame
// (size and samples are the probe's own). A stateful graph is reset after
// the probe. -v (`verbose`) prints the choice and where it came from, on
// stderr:
//   marchstudio: dispatch auto: compute 16x8 (cached for llvmpipe (...))
//   marchstudio: dispatch auto: probe: fragment 12.10 ms, compute 9.80 ms (8x8), 9.10 (16x8), ... a frame at 256x144: compute 16x8, cached in ...
DispatchChoice choose_dispatch(Dispatch requested, PassGraph& graph, const Program& post, const StillFrame& frame,
                               const Context& ctx, std::optional<ComputeGroup> group, bool verbose);

}  // namespace ms
