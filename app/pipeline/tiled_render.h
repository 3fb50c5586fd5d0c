// `render` of a huge still (docs/usage.md#huge-stills): past the memory
// budget or the GL's size limit, a stateless still (a scene, a single-pass
// Shadertoy shader) is drawn in tiles (render/tiled_still.h) and each band
// of rows streamed into the output's temporary (io/image_stream.h), so no
// more than a band is ever held; then verified and renamed into place.
// NaN/Inf pixels are counted band by band: with --strict any of them
// removes the temporary (exit 1, no file). A progress bar with an ETA is
// drawn on a terminal. SIGINT, SIGTERM and the --timeout watchdog remove
// the temporary before the process ends.
//
//   StillTiling t = plan_render_tiling(in, fp, targets, forced, max_w, max_h);
//   if (t.tiled()) render_tiled_file(file, session, still, t);
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/deadline.h"
#include "io/image_io.h"
#include "pipeline/frame_session.h"
#include "pipeline/input.h"
#include "pipeline/nonfinite.h"
#include "render/still.h"
#include "render/tiled_still.h"
#include "render/tiles.h"

namespace ms {

// Whether and how this still is tiled (plan_still_tiling) with `gpu_targets`
// buffers at fp's size, within max_w x max_h (the GL's limit; INT_MAX
// before a context exists). `forced`: the hidden --tile-still side (tests),
// 0 for none. A graph with buffers is never tiled: past a limit it is
// refused in one line naming --size.
StillTiling plan_render_tiling(const LoadedInput& in, const FrameParams& fp, int gpu_targets, int forced, int max_w,
                               int max_h);

struct TiledFile {
  std::filesystem::path output;
  std::vector<std::string> aov_names;  // appended after R, G, B, A (EXR)
  ImageMetadata meta;
  Watchdog* watchdog = nullptr;  // re-armed to remove the temporary before it ends the process
  const Deadline* deadline = nullptr;
  // The NaN/Inf pixels counted over every band are checked before the
  // file is finished: a throw (--strict) leaves no file.
  NonfiniteGuard nonfinite;
};

// Each tile drawn by the session's dispatch (pipeline/frame_session.h).
void render_tiled_file(const TiledFile& job, FrameSession& session, const StillFrame& still,
                       const StillTiling& tiling);

}  // namespace ms
