#include "cli/render_cmd.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>

#include "bench/bench.h"
#include "cli/sequence_cmd.h"
#include "cli/shader_dir.h"
#include "core/error.h"
#include "scene/quality.h"
#include "gl/context.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "render/aov.h"
#include "render/bounds_check.h"
#include "core/deadline.h"
#include "render/frame.h"
#include "render/graph.h"
#include "render/still.h"
#include "render/tiles.h"
#include "render/uniforms.h"
#include "scene/animation.h"
#include "cli/flag_checks.h"
#include "cli/fingerprint.h"
#include "cli/input.h"
#include "cli/tiled_render.h"
#include "live/render_watch.h"

namespace ms {
namespace fs = std::filesystem;

CLI::App* add_render_command(CLI::App& app, RenderArgs& a) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene (.toml) or a Shadertoy shader (.glsl) to an image");
  cmd->add_option("input", a.input, "Scene .toml or Shadertoy .glsl/.frag")->required();
  cmd->add_option("-o,--output", a.output, "Output image: .png .jpg .tif (8-bit sRGB) or .exr (linear float)")
      ->check(not_empty());
  cmd->add_option("--size", a.size, "Image size WxH (default: the scene's)")->check(not_empty());
  cmd->add_option("--time", a.time, "Scene time in seconds (default 0)")
      ->check(seconds_value())
      ->each([&a](const std::string&) { a.time_set = true; });
  cmd->add_option("--spp", a.spp, "Samples per pixel, stratified, 1..1024 (default: the scene's)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--frame", a.frame, "Frame number (uFrame / iFrame)");
  cmd->add_option("--backend", a.backend, "GL context: auto, egl or osmesa")
      ->check(one_of(kBackendNames));
  cmd->add_option("--shader-dir", a.shader_dir, "The sdf_shaders/ directory");
  cmd->add_option("--preset", a.preset,
                  "Quality preset: fast, balanced, reference or textbook (default: the scene's; its explicit "
                  "[quality] keys still apply)")
      ->check(one_of(quality_preset_names()));
  cmd->add_option("--disable", a.disable, "Switch effects off: shadows, reflections, ao, checker-filter")
      ->delimiter(',')
      ->check(one_of(kEffectNames));
  cmd->add_option("-D,--define", a.defines, "Inject #define NAME VALUE into the scene shader (NAME or NAME=VALUE)");
  cmd->add_option("--frames", a.frames, "Render frames A..B (both included) to -o PATTERN, e.g. out/f_%04d.png")
      ->check(not_empty());
  add_shadertoy_flags(cmd, a.shadertoy);
  add_override_flags(cmd, a.overrides);
  cmd->add_option("--fps", a.fps,
                  "Frames per second: frame f of --frames is at time f / fps (default 24; a Shadertoy shader's 60), "
                  "and a still of a shader with buffers replays round(time x fps) frames")
      ->each([&a](const std::string&) { a.fps_set = true; });
  cmd->add_option("--shard", a.shard, "Render only shard I of N (I/N, from 0) of --frames")->check(not_empty());
  cmd->add_option("--shard-mode", a.shard_mode, "How --shard splits the frames: stride (default) or chunk")
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
  cmd->add_flag("-v,--verbose", a.verbose, "Print the backend, GL renderer and timings");
  cmd->add_flag("--no-specialize", a.no_specialize,
                "Build the generic shader: every feature compiled, values as uniforms (docs/specialization.md)");
  cmd->add_flag("--print-shader", a.print_shader,
                "Print the assembled main-pass shader to stdout and exit; nothing is rendered");
  cmd->add_flag("--strict", a.strict,
                "Fail (exit 1, no file written) when any pixel has a NaN or Inf in its colour or AOVs; "
                "without it they are counted on stderr");
  cmd->add_flag("--watch", a.watch, "Render again on every save of the scene or a file it includes, until Ctrl+C");
  cmd->add_option("--allow-include", a.allow_include,
                  "Let #include read files under DIR too (default: the scene's directory and the shader dir)");
  cmd->add_option("--timeout", a.timeout,
                  "Give up after SECONDS per image (each frame of --frames): exit 3, no file written");
  cmd->add_option("--tile-size", a.tile_size, "Largest square one draw covers, pixels (0: the whole frame)")
      ->check(CLI::NonNegativeNumber)
      ->group("");  // tests and experiments: the image is the same for any value
  cmd->add_option("--tile-still", a.tile_still,
                  "Draw the still in tiles of at most SIDE pixels, streamed to the file (0: only past the limits)")
      ->check(CLI::NonNegativeNumber)
      ->group("");  // tests: a tiled still is bit-identical to a whole one (docs/usage.md#huge-stills)
  return cmd;
}

namespace {

// Seconds since the last lap, for --verbose phase timings.
struct Stopwatch {
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  }
};

}  // namespace

// --watch: this same function without --watch, after every save; the files
// to watch are whatever loading the input reads.
static int run_render_watch(const RenderArgs& a) {
  if (wants_sequence(a)) fail_input("--watch renders one image, not a --frames sequence", {}, 0, "--watch");
  RenderArgs once = a;
  once.watch = false;
  live::WatchRenderOptions w;
  w.render = [once] { run_render(once); };
  w.files = [&a] {
    AssembleOptions opts{resolve_shader_dir(a.shader_dir), parse_defines(a.defines),
                         parse_allow_include(a.allow_include)};
    opts.uniforms = a.overrides.uniforms;
    std::vector<fs::path> files = {a.input};
    for (const PassSource& pass : load_input(a.input, a.disable, opts, a.preset, a.overrides.set).passes)
      for (const fs::path& p : pass.source.dependencies) files.push_back(p);
    return files;
  };
  return live::watch_and_render(w);
}

int run_render(const RenderArgs& a) {
  if (!std::isfinite(a.timeout) || a.timeout < 0)
    fail_input("--timeout must be a number of seconds >= 0 (0: no limit)", {}, 0, "--timeout");
  if (a.watch) return run_render_watch(a);
  if (wants_sequence(a)) return run_sequence(a);
  if (a.force)
    fail_input("--force needs --frames: a still always replaces its file", {}, 0, "--force",
               "it makes a sequence render again the frames it would keep");
  // From here on the image has a.timeout seconds; the watchdog ends the
  // process if a draw (or the driver's compile) never returns.
  const Deadline deadline = Deadline::after(a.timeout);
  std::optional<Watchdog> watchdog;
  if (deadline.limited()) watchdog.emplace().arm(deadline, "the render");
  if (!std::isfinite(a.time)) fail_input("--time must be a finite number", {}, 0, "--time");
  if (a.spp < 0 || a.spp > 1024) fail_input("--spp must be in 1..1024", {}, 0, "--spp");
  if (a.frame < 0) fail_input("--frame must be >= 0", {}, 0, "--frame");
  const Backend backend = parse_backend(a.backend);
  const fs::path input = a.input;
  const fs::path output = a.output.empty() ? fs::path(input.stem().string() + ".png") : fs::path(a.output);
  if (has_frame_field(output.string()))
    fail_input("the output '" + output.string() + "' has a frame field but there is no --frames", {}, 0, "--frames",
               "e.g. --frames 0..59 -o " + output.string() + "; for one image name a file without %d");
  check_output_path(output);  // before any work: no file is ever half-made
  const bool display = is_display_format(image_format_for(output));
  const bool aovs = !a.aov.empty();
  const std::vector<std::string> aov_names = aovs ? aov_channels(a.aov) : std::vector<std::string>{};
  if (aovs && display)
    fail_input("--aov needs an .exr output, not '" + output.filename().string() + "'", {}, 0, "--aov",
               "AOVs are extra float channels, which only OpenEXR holds");

  AssembleOptions opts{resolve_shader_dir(a.shader_dir), parse_defines(a.defines),
                       parse_allow_include(a.allow_include)};
  if (aovs) for (const auto& d : aov_defines()) opts.defines.push_back(d);
  opts.specialize = a.no_specialize ? Specialization::generic : Specialization::folded;
  opts.uniforms = a.overrides.uniforms;
  LoadedInput in = load_input_scene(input, a.disable, a.preset, a.overrides.set);
  if (aovs && in.shadertoy)
    fail_input("--aov needs a scene: a Shadertoy shader has no AOV outputs", input.string(), 0, "--aov");
  apply_shadertoy_flags(in, a.shadertoy);
  if (a.fps_set) {
    if (!std::isfinite(a.fps) || a.fps <= 0) fail_input("--fps must be a positive number", {}, 0, "--fps");
    in.scene.shadertoy.fps = a.fps;
  }
  const Scene& scene = in.scene;
  FrameParams fp;
  fp.width = scene.render.width;
  fp.height = scene.render.height;
  if (!a.size.empty()) {
    const ImageSize s = parse_size_flag(a.size);
    fp.width = s.width;
    fp.height = s.height;
  }
  fp.spp = a.spp > 0 ? a.spp : scene.render.spp;
  const ShaderSource post_src = assemble_still(in, opts, fp.spp, aovs, display, fp.fused_post);
  if (a.print_shader) {
    for (const PassSource& pass : in.passes) {
      if (in.passes.size() > 1) std::printf("// ==== marchstudio: pass %s ====\n", pass.name.c_str());
      std::fputs(pass.source.text.c_str(), stdout);
    }
    return 0;
  }
  if (in.stateful() && a.frame != 0)
    fail_input("--frame conflicts with a shader that has buffers: its still replays frames 0..N, N = round(time x fps)",
               {}, 0, "--frame", "give --time (and --fps) instead");
  report_input_warnings(in.warnings, input.string(), a.strict);
  fp.exposure = scene.render.exposure;
  fp.aovs = aovs;
  fp.deadline = deadline.limited() ? &deadline : nullptr;
  fp.tile_size = a.tile_size;
  // Before the (slow) context: past the memory budget a still is drawn in
  // tiles (cli/tiled_render.h), and one with buffers is refused.
  const int buffer_targets = 2 * (static_cast<int>(in.passes.size()) - 1);  // each buffer's two textures
  const int gpu_targets = (aovs ? 6 : 2) + buffer_targets;
  plan_render_tiling(in, fp, gpu_targets, a.tile_still, INT_MAX, INT_MAX);
  const float time = a.time_set ? static_cast<float>(a.time) : scene.render.time;
  const Scene posed = animated(scene, time);  // [[animation]] keyframes at this time
  fp.exposure = posed.render.exposure;

  Stopwatch clock;
  std::unique_ptr<Context> ctx = create_headless_context(backend);
  const double t_context = clock.lap();
  if (a.verbose) {
    std::fprintf(stderr, "marchstudio: backend %s, GL_RENDERER %s, GL_VERSION %s\n", ctx->backend().c_str(),
                 ctx->info().renderer.c_str(), ctx->info().version.c_str());
    if (!in.shadertoy)
      std::fprintf(stderr, "marchstudio: shader %s (%s)\n", specialization_name(opts.specialize),
                   describe(scene_features(scene, opts)).c_str());
  }
  const StillTiling tiling = plan_render_tiling(in, fp, gpu_targets, a.tile_still, gl_max_width(ctx->info()),
                                                gl_max_height(ctx->info()));
  if (!tiling.tiled()) check_frame_size(ctx->info(), fp.width, fp.height, aovs ? 6 : 2);

  PassGraph graph(in.passes);
  const Program post_prog(fullscreen_vertex_source(), post_src);
  const double t_compile = clock.lap();
  report_input_warnings(unbound_warnings(graph), input.string(), a.strict);
  if (a.verbose && !in.shadertoy) {  // does [bounds] hold what map() draws? (render/bounds_check.h)
    const std::string w = bounds_warning(input.string(), check_bounds(posed, opts, [&](const Program& p) {
      set_scene_uniforms(p, posed, fp.width, fp.height, time, a.frame);
    }));
    if (!w.empty()) std::fprintf(stderr, "marchstudio: %s\n", w.c_str());
  }
  FrameRenderer renderer(*ctx);
  StillFrame still;
  still.in.scene = &posed;
  still.in.time = time;
  still.in.frame = a.frame;
  std::copy(std::begin(scene.shadertoy.mouse), std::end(scene.shadertoy.mouse), still.in.mouse);
  still.fps = scene.shadertoy.fps;
  still.params = fp;
  // The NaN/Inf guard: pixels with NaN/Inf in any channel read back
  // (colour, AOVs), and those a Shadertoy Image pass flagged, counted over
  // everything before the file is made.
  const auto check_nonfinite = [&](long long nonfinite) {
    if (nonfinite <= 0) return;
    const std::string what = std::to_string(nonfinite) + " of " +
                             std::to_string(static_cast<long long>(fp.width) * fp.height) +
                             " pixels have NaN/Inf values";
    if (a.strict) throw Error({Exit::threshold, input.string(), 0, "--strict", what + "; nothing written", {}, {}});
    std::fprintf(stderr, "marchstudio: %s: warning: %s (--strict makes this an error)\n", input.string().c_str(),
                 what.c_str());
  };
  ImageMetadata meta{{"Software", "marchstudio 0.1.0"},
                     {"ImageDescription", input.filename().string() + " t=" + std::to_string(time) +
                                              " spp=" + std::to_string(fp.spp)}};
  add_fingerprint(meta, frame_fingerprint(job_fingerprint(in, fp, post_src, aov_names, scene.shadertoy.fps), a.frame,
                                          time));
  if (tiling.tiled()) {  // rendered and written band by band
    render_tiled_file({output, aov_names, meta, watchdog ? &*watchdog : nullptr, &deadline, check_nonfinite},
                      renderer, graph, post_prog, still, tiling);
    if (a.verbose)
      std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render and write %.1f ms (tiles of %dx%d)\n",
                   t_context * 1e3, t_compile * 1e3, clock.lap() * 1e3, tiling.tile_width, tiling.band_height);
    std::printf("%s\n", output.string().c_str());
    return 0;
  }
  Still out = render_still(renderer, graph, post_prog, still);
  Image img = std::move(out.color);
  check_nonfinite(count_nonfinite_pixels(img, aovs ? &out.aovs : nullptr) + out.flagged);
  if (aovs) img = append_channels(img, select_channels(out.aovs, aov_names));
  const double t_render = clock.lap();
  deadline.check("the render");
  if (watchdog) watchdog->disarm();  // the write is atomic and must not be cut short
  write_image(img, output, meta);
  if (a.verbose)
    std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render %.1f ms, write %.1f ms\n",
                 t_context * 1e3, t_compile * 1e3, t_render * 1e3, clock.lap() * 1e3);
  std::printf("%s\n", output.string().c_str());
  return 0;
}

}  // namespace ms
