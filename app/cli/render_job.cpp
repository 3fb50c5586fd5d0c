#include "cli/render_job.h"

#include <cmath>

#include "cli/flag_checks.h"
#include "cli/load_flags.h"
#include "cli/render_cmd.h"
#include "core/error.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "pipeline/shader_dir.h"
#include "render/aov.h"
#include "scene/quality.h"

namespace ms {
namespace fs = std::filesystem;

FrameJob make_render_job(const RenderArgs& a, const fs::path& input, const fs::path& output) {
  FrameJob job;
  job.label = input.string();
  job.input = input;
  if (!std::isfinite(a.timeout) || a.timeout < 0)
    fail_input("--timeout must be a number of seconds >= 0 (0: no limit)", {}, 0, "--timeout");
  job.timeout = a.timeout;
  if (a.time && !std::isfinite(*a.time)) fail_input("--time must be a finite number", {}, 0, "--time");
  if (a.time) job.time = static_cast<float>(*a.time);
  if (a.spp < 0 || a.spp > 1024) fail_input("--spp must be in 1..1024", {}, 0, "--spp");
  job.spp = a.spp;
  if (a.frame && *a.frame < 0) fail_input("--frame must be >= 0", {}, 0, "--frame");
  job.frame = a.frame;
  if (a.fps) {
    if (!std::isfinite(*a.fps) || *a.fps <= 0) fail_input("--fps must be a positive number", {}, 0, "--fps");
    job.fps = a.fps;
  }
  if (a.tile_size < 0) fail_input("--tile-size must be >= 0", {}, 0, "--tile-size");
  if (a.tile_still < 0) fail_input("--tile-still must be >= 0", {}, 0, "--tile-still");
  job.tile_size = a.tile_size;
  job.tile_still = a.tile_still;
  job.backend = a.backend;
  job.size = a.size;
  // A --jobs line's names arrive without the flags' validators: checked here.
  if (!a.load.preset.empty()) check_one_of(a.load.preset, quality_preset_names(), "--preset");
  for (const std::string& n : a.aov) check_one_of(n, kAovNames, "--aov");
  set_load_fields(job, a.load);
  if (!a.aov.empty()) job.aov_channels = aov_channels(a.aov);
  job.strict = a.strict;
  job.verbose = a.verbose;
  job.dispatch = a.dispatch;  // auto: chosen once the context exists (pipeline/dispatch_probe.h)
  job.compute_group = a.compute_group;

  job.output = !output.empty()     ? output
               : !a.output.empty() ? fs::path(a.output)
                                   : fs::path(input.stem().string() + ".png");
  if (has_frame_field(job.output.string()))
    fail_input("the output '" + job.output.string() + "' has a frame field but there is no --frames", {}, 0,
               "--frames", "e.g. --frames 0..59 -o " + job.output.string() + "; for one image name a file without %d");
  check_output_path(job.output);  // before any work: no file is ever half-made
  if (job.aovs() && is_display_format(image_format_for(job.output)))
    fail_input("--aov needs an .exr output, not '" + job.output.filename().string() + "'", {}, 0, "--aov",
               "AOVs are extra float channels, which only OpenEXR holds");
  return job;
}

}  // namespace ms
