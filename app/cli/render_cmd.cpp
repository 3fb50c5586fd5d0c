#include "cli/render_cmd.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/batch.h"
#include "cli/common_flags.h"
#include "cli/flag_checks.h"
#include "cli/frame_flags.h"
#include "cli/glslviewer_flags.h"
#include "cli/input_flags.h"
#include "cli/render_job.h"
#include "cli/sequence_cmd.h"
#include "core/error.h"
#include "live/render_watch.h"
#include "pipeline/input.h"
#include "pipeline/shader_dir.h"
#include "pipeline/still_job.h"
#include "render/aov.h"

namespace ms {
namespace fs = std::filesystem;

CLI::App* add_render_command(CLI::App& app, RenderArgs& a) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene (.toml), a graph file (.json) or a Shadertoy shader (.glsl) to an image");
  cmd->add_option("input", a.inputs,
                  "Scene .toml, graph file .json, or Shadertoy .glsl/.frag/.json; several make a batch (see --output-dir)");
  cmd->add_option("-o,--output", a.output,
                  "Output image: .png .jpg .tif (8-bit sRGB) or .exr (linear float) (default: <stem>.png, the "
                  "input's file name stem, in the current directory)")
      ->check(not_empty());
  cmd->add_option("--output-dir", a.output_dir,
                  "Render every input, in one process, to DIR/<stem>.<format>; a --jobs line's relative \"output\" "
                  "is under DIR too (docs/usage.md#batches)")
      ->check(not_empty());
  cmd->add_option_function<std::string>(
         "--format", [&a](const std::string& v) { a.format = image_format_for("x." + v); },
         "Extension of outputs named from the input: png (default), exr, tif, jpg")
      ->check(one_of({"png", "exr", "tif", "jpg"}));
  cmd->add_option("--jobs", a.jobs,
                  "Render the stills listed in FILE, one JSON object per line with \"scene\", \"output\" and any "
                  "flag without its dashes; the command line's flags are the defaults")
      ->check(not_empty());
  add_size_flag(cmd, "--size", a.size, "Image size WxH (default: the scene's)")->check(not_empty());
  cmd->add_option_function<double>(
         "--time", [&a](double v) { a.time = v; },
         "Scene time in seconds, any finite value (default: the scene's [render] time, else 0)")
      ->check(seconds_value());
  cmd->add_option("--spp", a.spp, "Samples per pixel, stratified, 1..1024 (default: the scene's)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option_function<int>(
      "--frame", [&a](int v) { a.frame = v; }, "Frame number (uFrame / iFrame; default round(time x fps), 0 at time 0)");
  add_backend_flag(cmd, a.backend);
  add_load_flags(cmd, a.load);
  cmd->add_option_function<std::string>(
         "--frames", [&a](const std::string& v) { a.frames = parse_frame_range(v); },
         "Render frames A..B (both included) to -o PATTERN, e.g. out/f_%04d.png")
      ->check(not_empty());
  add_dispatch_flag(cmd, a.dispatch,
                    "Draw the scene pass as a fragment pass (default), a compute dispatch, or auto (docs/gpu.md)");
  add_compute_group_flag(cmd, a.compute_group);
  cmd->add_option_function<double>("--fps", [&a](double v) { a.fps = v; },
                  "Frames per second: frame f of --frames is at time f / fps (default 24; a Shadertoy shader's 60), "
                  "and a still of a shader with buffers replays round(time x fps) frames");
  cmd->add_option_function<std::string>(
         "--shard", [&a](const std::string& v) { a.shard = parse_shard(v); },
         "Render only shard I of N (I/N, from 0) of --frames")
      ->check(not_empty());
  cmd->add_option_function<std::string>(
         "--shard-mode", [&a](const std::string& v) { a.shard_mode = parse_shard_mode(v); },
         "How --shard splits the frames: stride (default) or chunk")
      ->check(one_of({"stride", "chunk"}));
  cmd->add_option("--video", a.video, "Encode the --frames sequence with ffmpeg into this file (e.g. out.mp4)")
      ->check(not_empty());
  cmd->add_flag("--force", a.force,
                "With --frames: render every frame again, even those on disk with this run's fingerprint");
  cmd->add_flag("--no-write", a.no_write, "Render --frames but write nothing (throughput measurements)")
      ->group("");
  cmd->add_option("--aov", a.aov,
                  "Add AOV channels to the .exr: depth, normal, steps, material, shadow, ao, cost, hit "
                  "(see docs/usage.md)")
      ->delimiter(',')
      ->check(one_of(kAovNames));
  cmd->add_flag("-v,--verbose", a.verbose,
                "Print the backend, GL renderer, the shader dir and image module used, and timings");
  cmd->add_flag("--print-shader", a.print_shader,
                "Print the assembled main-pass shader to stdout and exit; nothing is rendered");
  cmd->add_flag("--strict", a.strict,
                "Fail (exit 1, no file written) when any pixel has a NaN or Inf in its colour or AOVs, or map() "
                "crosses [bounds]; without it they are warnings on stderr");
  cmd->add_flag("--watch", a.watch, "Render again on every save of the scene or a file it includes, until Ctrl+C");
  cmd->add_option("--timeout", a.timeout,
                  "Give up after SECONDS per image (each frame of --frames): exit 3, no file written");
  // Hidden: tests and experiments, the image is the same for any value
  // (a tiled still is bit-identical to a whole one, docs/usage.md#huge-stills).
  add_hidden_pixels(cmd, "--tile-size", a.tile_size, "Largest square one draw covers, pixels (0: the whole frame)");
  add_hidden_pixels(cmd, "--tile-still", a.tile_still,
                    "Draw the still in tiles of at most SIDE pixels, streamed to the file (0: only past the limits)");
  return cmd;
}

// --watch: this same function without --watch, after every save; the files
// to watch are whatever loading the input reads.
static int run_render_watch(const RenderArgs& a) {
  if (wants_sequence(a)) fail_input("--watch renders one image, not a --frames sequence", {}, 0, "--watch");
  RenderArgs once = a;
  once.watch = false;
  live::WatchRenderOptions w;
  w.render = [once] { run_render(once); };
  w.files = [&a] {
    AssembleOptions opts{resolve_shader_dir(a.load.shader_dir), a.load.defines,
                         parse_allow_include(a.load.allow_include)};
    opts.uniforms = a.load.overrides.uniforms;
    std::vector<fs::path> files = {a.input};
    for (const PassSource& pass :
         load_input(a.input, parse_disabled(a.load.disable), opts, a.load.preset, a.load.overrides.set).passes)
      for (const fs::path& p : pass.source.dependencies) files.push_back(p);
    return files;
  };
  return live::watch_and_render(w);
}

int run_render(const RenderArgs& args) {
  refuse_image_inputs(args.inputs);  // glslViewer's positional images (cli/glslviewer_flags.h)
  if (wants_batch(args)) return run_batch(args);
  if (args.inputs.empty())
    fail_input("no input: give a scene .toml or a shader, or --jobs FILE", {}, 0, "input",
               "e.g. marchstudio render scenes/seed.toml -o seed.png");
  RenderArgs a = args;
  a.input = args.inputs.front();
  if (!std::isfinite(a.timeout) || a.timeout < 0)
    fail_input("--timeout must be a number of seconds >= 0 (0: no limit)", {}, 0, "--timeout");
  if (a.watch) return run_render_watch(a);
  if (wants_sequence(a)) {
    if (a.format) fail_input("--format names a still's output; a sequence's is -o PATTERN", {}, 0, "--format");
    return run_sequence(a);
  }
  if (a.force)
    fail_input("--force needs --frames: a still always replaces its file", {}, 0, "--force",
               "it makes a sequence render again the frames it would keep");
  if (a.format && !a.output.empty())
    fail_input("--format names outputs made from the input's stem, and -o names the file", {}, 0, "--format",
               "give the extension in -o");
  const FrameJob job = make_render_job(a, a.input, a.output.empty() ? batch_output(a, a.input) : fs::path{});
  if (a.print_shader) {
    print_job_shader(job);
    return 0;
  }
  say_removed_temps({job.output});
  FrameSession session;
  render_still_job(job, session);
  std::printf("%s\n", job.output.string().c_str());
  return 0;
}

}  // namespace ms
