// One still to render, as typed and checked values: what `render`'s flags
// (or one line of a --jobs file, cli/job_list.h) become in cli/, and the
// only thing the still pipeline (cli/still_job.h) reads. Nothing below cli/
// sees a flag string: sizes, backends, dispatches and defines arrive typed,
// parsed as the flag (or the job's key) was read; AOV names and include
// directories are checked here; every error names its flag.
//
//   RenderJob job = make_render_job(args, args.inputs[0]);  // throws ms::Error
//   render_still_job(job, session);                          // cli/still_job.h
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/input.h"
#include "cli/dispatch_flag.h"
#include "cli/override_flags.h"
#include "gl/context.h"
#include "render/tiles.h"
#include "shader/assemble.h"

namespace ms {

struct RenderArgs;

struct RenderJob {
  // How a batch names this job in its errors: "jobs.jsonl:3", or the input.
  std::string label;
  std::filesystem::path input;
  std::filesystem::path output;      // never empty: <input stem>.png when no -o
  ImageSize size;                    // 0x0: the scene's
  int spp = 0;                       // 1..1024; 0: the scene's
  std::optional<float> time;         // seconds; empty: the scene's
  std::optional<int> frame;          // uFrame / iFrame, >= 0; empty: the still's frame (still_frame_of)
  std::optional<double> fps;         // > 0; empty: the scene's (a Shadertoy shader's 60)
  Backend backend = Backend::automatic;
  std::filesystem::path shader_dir;  // resolved: holds main.frag
  std::vector<std::string> disable;  // effect names, each one of kEffectNames
  std::string preset;                // a quality preset name; empty: the scene's
  std::vector<std::pair<std::string, std::string>> defines;  // -D, parsed
  std::vector<std::filesystem::path> allow_include;          // canonical directories
  Overrides overrides;               // --set, --uniform
  std::vector<std::string> aov_channels;  // render/aov.h's channels; empty: no AOVs
  Specialization specialize = Specialization::folded;
  bool strict = false;
  double timeout = 0.0;              // seconds for this image; 0: none
  int tile_size = kTileSize;         // largest square per draw (render/tiles.h)
  int tile_still = 0;                // forced tiled-still side (tests); 0: past the limits only
  ShadertoyFlags shadertoy;
  Dispatch dispatch = Dispatch::fragment;  // --dispatch; automatic: cli/dispatch_probe.h chooses
  std::optional<ComputeGroup> compute_group;  // --compute-group; none: 8x8, or auto's measured group
  bool verbose = false;

  bool aovs() const { return !aov_channels.empty(); }
};

// The job for `input` under args' flags (args.input and args.inputs are
// not read; args.output is, unless `output` is given). Throws bad_input
// naming the flag of the first bad value; the output path is checked as
// check_output_path() does, so a job that passes leaves no file half-made.
RenderJob make_render_job(const RenderArgs& args, const std::filesystem::path& input,
                          const std::filesystem::path& output = {});

}  // namespace ms
