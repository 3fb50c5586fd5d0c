// `marchstudio render`: a scene (.toml) or a Shadertoy shader (.glsl) to an
// image file, headless.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/load_flags.h"
#include "gl/context.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "pipeline/frame_job.h"
#include "render/compute_frame.h"
#include "render/tiles.h"
#include "shader/compute_wrap.h"

namespace CLI {
class App;
}

namespace ms {

// The flags as given; cli/render_job.h turns them into FrameJobs, which is
// all the still pipeline reads.

struct RenderArgs {
  std::vector<std::string> inputs;  // positional: one, or a batch of several (cli/batch.h)
  std::string input;      // the one input of a still, a sequence or --watch (inputs[0])
  std::string output;     // empty: <input stem>.png in the current directory
  std::string output_dir; // a batch's DIR/<stem>.<format>
  std::optional<ImageFormat> format;  // --format: outputs named from the input; none: png
  std::string jobs;       // --jobs FILE: JSON lines, one still each (cli/job_list.h)
  ImageSize size;         // --size WxH; 0x0: the scene's
  std::optional<double> time;  // seconds; none: the scene's, never the wall clock
  int spp = 0;            // 0: the scene's
  std::optional<int> frame;  // none: a still's frame is round(time x fps)
  Backend backend = Backend::automatic;
  LoadFlags load;  // shader dir, includes, -D, preset, --disable, --set ... (cli/load_flags.h)
  // Sequences (cli/sequence_cmd.h): --frames turns `render` into one.
  std::optional<FrameRange> frames;  // --frames A..B, both included
  std::optional<double> fps;  // time of frame f is f / fps; none: kSceneFps, or a shader's own
  std::optional<Shard> shard;           // --shard I/N
  std::optional<ShardMode> shard_mode;  // none: stride
  std::string video;       // encode the frames with ffmpeg afterwards
  bool no_write = false;   // hidden: render but discard (throughput measurements)
  bool force = false;      // a sequence renders every frame again (pipeline/sequence_state.h)
  bool verbose = false;
  bool watch = false;       // re-render on every save of the scene or its includes (live/render_watch.h)
  std::vector<std::string> aov;      // AOVs to add to an .exr: depth, normal, steps, material, shadow, ao, cost, hit
  bool print_shader = false;   // print the assembled scene shader and exit
  bool strict = false;         // any NaN/Inf pixel (colour or AOV) is an error: exit 1, nothing written
  double timeout = 0.0;      // seconds per image (each frame of --frames); 0: none (core/deadline.h)
  int tile_size = kTileSize; // hidden --tile-size: largest square per draw (render/tiles.h); 0: whole frame
  int tile_still = 0;        // hidden --tile-still: draw and stream the still in tiles of this side (tests); 0: past the limits only
  Dispatch dispatch = Dispatch::fragment;  // --dispatch fragment|compute|auto (cli/dispatch_flag.h)
  std::optional<ComputeGroup> compute_group;  // hidden --compute-group WxH; none: 8x8, or auto's measured group
};

CLI::App* add_render_command(CLI::App& app, RenderArgs& args);
int run_render(const RenderArgs& args);

}  // namespace ms
