#include "cli/sequence_cmd.h"

#include <cmath>
#include <string>

#include "cli/load_flags.h"
#include "cli/render_cmd.h"
#include "core/error.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "io/video.h"
#include "pipeline/sequence.h"
#include "pipeline/shader_dir.h"
#include "render/aov.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Everything decided from the flags before any file is read.
struct Plan {
  FrameRange range;
  Shard shard;
  ShardMode mode = ShardMode::stride;
  double fps = kSceneFps;
  std::string pattern;
};

Plan plan_from_flags(const RenderArgs& a) {
  if (!a.frames)
    fail_input("--shard, --shard-mode, --video and --no-write need --frames", {}, 0, "--frames",
               "e.g. --frames 0..59 --fps 24 -o out/frame_%04d.png");
  if (a.time)
    fail_input("--time conflicts with --frames: each frame's time is frame / fps", {}, 0, "--time",
               "shift the animation with --frames instead");
  if (a.frame.value_or(0) != 0) fail_input("--frame conflicts with --frames", {}, 0, "--frame");
  if (a.spp < 0 || a.spp > 1024) fail_input("--spp must be in 1..1024", {}, 0, "--spp");
  Plan p;
  p.range = *a.frames;
  p.fps = a.fps.value_or(kSceneFps);
  if (!std::isfinite(p.fps) || p.fps <= 0)
    fail_input("--fps must be a positive number, got " + std::to_string(p.fps), {}, 0, "--fps");
  if (a.shard) p.shard = *a.shard;
  if (a.shard_mode) p.mode = *a.shard_mode;
  if (a.output.empty()) {
    // <stem>_%04d.png, with any '%' of the stem escaped for the pattern.
    for (char c : fs::path(a.input).stem().string()) p.pattern += c == '%' ? std::string("%%") : std::string(1, c);
    p.pattern += "_%04d.png";
  } else {
    p.pattern = a.output;
  }
  if (!a.video.empty()) {
    if (p.shard.count > 1)
      fail_input("--video needs the whole sequence, not one shard of it", {}, 0, "--video",
                 "encode once every shard has finished: rerun without --shard, which skips the finished frames");
    if (a.no_write) fail_input("--video needs the frames written; drop --no-write", {}, 0, "--video");
    check_video_path(a.video);
  }
  return p;
}

}  // namespace

bool wants_sequence(const RenderArgs& a) {
  return a.frames || a.shard || a.shard_mode || !a.video.empty() || a.no_write;
}

int run_sequence(const RenderArgs& a) {
  // Flags, output pattern and ffmpeg are checked here; scene, shaders and
  // every frame's pose before the GL context exists: bad input never leaves a file.
  const Plan plan = plan_from_flags(a);
  SequenceJob job;
  job.pattern = FramePattern(plan.pattern);
  job.range = plan.range;
  job.shard = plan.shard;
  job.mode = plan.mode;
  check_output_path(job.pattern.path(plan.range.first));
  const bool display = is_display_format(image_format_for(job.pattern.path(plan.range.first)));
  if (!a.aov.empty() && display) fail_input("--aov needs an .exr output pattern", plan.pattern, 0, "--aov");
  if (!a.video.empty()) {
    if (!display) fail_input("--video needs PNG, JPEG or TIFF frames, not EXR", plan.pattern, 0, "--video");
    job.ffmpeg = find_on_path("ffmpeg");
    if (job.ffmpeg.empty())
      throw Error(ErrorInfo{Exit::system, {}, 0, "--video", "ffmpeg is not installed (not found on PATH)",
                            "install it (Debian: apt-get install ffmpeg), or drop --video and encode the frames later", {}});
    job.video = a.video;
  }
  job.no_write = a.no_write;
  job.force = a.force;
  FrameJob& f = job.frame;
  f.label = a.input;
  f.input = a.input;
  f.size = a.size;
  f.spp = a.spp;
  if (a.fps) f.fps = plan.fps;
  f.backend = a.backend;
  set_load_fields(f, a.load);
  if (!a.aov.empty()) f.aov_channels = aov_channels(a.aov);
  f.strict = a.strict;
  f.timeout = a.timeout;
  f.tile_size = a.tile_size;
  f.dispatch = a.dispatch;
  f.compute_group = a.compute_group;
  f.verbose = a.verbose;
  return render_sequence(job);
}

}  // namespace ms
