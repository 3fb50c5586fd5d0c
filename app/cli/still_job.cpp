#include "cli/still_job.h"

#include <chrono>
#include <climits>
#include <cstdio>
#include <optional>

#include "bench/bench.h"
#include "cli/bloom_setup.h"
#include "cli/dispatch_probe.h"
#include "cli/fingerprint.h"
#include "cli/input.h"
#include "cli/render_cmd.h"
#include "cli/tiled_render.h"
#include "core/deadline.h"
#include "core/error.h"
#include "core/version.h"
#include "io/direct_codec.h"
#include "io/image_backend.h"
#include "io/image_io.h"
#include "io/temp_cleanup.h"
#include "render/aov.h"
#include "render/compute_frame.h"
#include "render/frame.h"
#include "render/graph.h"
#include "render/still.h"
#include "render/uniforms.h"
#include "scene/animation.h"
#include "shader/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

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

// Everything decided before a context exists: bad input fails here.
struct PreparedStill {
  AssembleOptions opts;
  LoadedInput in;
  FrameParams fp;
  ShaderSource post_src;
  bool display = true;
};

PreparedStill prepare_still(const RenderJob& job) {
  PreparedStill p;
  p.display = is_display_format(image_format_for(job.output));
  const bool aovs = job.aovs();
  p.opts = AssembleOptions{job.shader_dir, job.defines, job.allow_include};
  if (aovs) for (const auto& d : aov_defines()) p.opts.defines.push_back(d);
  p.opts.specialize = job.specialize;
  p.opts.uniforms = job.overrides.uniforms;
  p.in = load_input_scene(job.input, job.disable, job.preset, job.overrides.set);
  if (aovs && p.in.shadertoy)
    fail_input("--aov needs a scene: a Shadertoy shader has no AOV outputs", job.input.string(), 0, "--aov");
  apply_shadertoy_flags(p.in, job.shadertoy);
  if (job.fps) p.in.scene.shadertoy.fps = *job.fps;
  const Scene& scene = p.in.scene;
  p.fp.width = job.size.width > 0 ? job.size.width : scene.render.width;
  p.fp.height = job.size.height > 0 ? job.size.height : scene.render.height;
  p.fp.spp = job.spp > 0 ? job.spp : scene.render.spp;
  p.post_src = assemble_still(p.in, p.opts, p.fp.spp, aovs, p.display, p.fp.fused_post);
  return p;
}

// The context for this job: the session's, made now if it is the first.
Context& session_context(RenderSession& session, Backend backend) {
  if (!session.context) {
    session.context = create_headless_context(backend);
    session.backend = backend;
  } else if (session.backend != backend) {
    fail_input(std::string("a batch draws in one GL context, made with --backend ") + backend_name(session.backend) +
                   "; this job asks for " + backend_name(backend),
               {}, 0, "--backend", "give every job of the batch the same --backend");
  }
  return *session.context;
}

}  // namespace

void say_removed_temps(const std::vector<fs::path>& outputs) {
  for (const fs::path& t : remove_dead_temps(outputs))
    std::fprintf(stderr, "marchstudio: removed %s, left by an interrupted run\n", t.string().c_str());
}

void print_job_shader(const RenderJob& job) {
  const PreparedStill p = prepare_still(job);
  for (const PassSource& pass : p.in.passes) {
    if (p.in.passes.size() > 1) std::printf("// ==== marchstudio: pass %s ====\n", comment_label(pass.name).c_str());
    std::fputs(pass.source.text.c_str(), stdout);
  }
}

void render_still_job(const RenderJob& job, RenderSession& session) {
  // From here on the image has job.timeout seconds; the watchdog ends the
  // process if a draw (or the driver's compile) never returns.
  const Deadline deadline = Deadline::after(job.timeout);
  std::optional<Watchdog> watchdog;
  if (deadline.limited()) watchdog.emplace().arm(deadline, "the render");
  const fs::path& input = job.input;
  const fs::path& output = job.output;
  const bool aovs = job.aovs();
  PreparedStill p = prepare_still(job);
  LoadedInput& in = p.in;
  FrameParams& fp = p.fp;
  const Scene& scene = in.scene;
  const float time = job.time ? *job.time : scene.render.time;
  // The frame a sequence at this fps draws at `time`, as Shadertoy at 1 s
  // has drawn 60: a scene's fps is --fps's default, a shader's its own.
  const double fps = in.shadertoy || job.fps ? scene.shadertoy.fps : kSceneFps;
  const int frame = job.frame.value_or(still_frame_number(time, fps));
  if (in.stateful() && frame != still_frame_number(time, fps))
    fail_input("--frame " + std::to_string(frame) + " conflicts with a shader that has buffers: its still replays "
                   "frames 0..N, N = round(time x fps) = " + std::to_string(still_frame_number(time, fps)),
               {}, 0, "--frame", "give --time (and --fps) instead");
  report_input_warnings(in.warnings, input.string(), job.strict);
  fp.exposure = scene.render.exposure;
  fp.aovs = aovs;
  fp.deadline = deadline.limited() ? &deadline : nullptr;
  fp.tile_size = job.tile_size;
  // Before the (slow) context: past the memory budget a still is drawn in
  // tiles (cli/tiled_render.h), and one with buffers is refused.
  const int buffer_targets = 2 * (static_cast<int>(in.passes.size()) - 1);  // each buffer's two textures
  const int gpu_targets = (aovs ? 6 : 2) + buffer_targets;
  plan_render_tiling(in, fp, gpu_targets, job.tile_still, INT_MAX, INT_MAX);
  const Scene posed = animated(scene, time);  // [[animation]] keyframes at this time
  fp.exposure = posed.render.exposure;

  Stopwatch clock;
  const bool fresh_context = !session.context;
  Context& ctx = session_context(session, job.backend);
  // A TIFF or JPEG needs the image module (PNG and EXR do not: io/direct_codec.h):
  // it loads while the shaders compile and the frame renders, not before the
  // context, whose driver dlopen would wait for it (io/image_backend.h).
  if (!writes_directly(image_format_for(output))) preload_image_backend();
  const double t_context = clock.lap();
  if (job.verbose) {
    if (fresh_context)
      std::fprintf(stderr, "marchstudio: backend %s, GL_RENDERER %s, GL_VERSION %s\n", ctx.backend().c_str(),
                   ctx.info().renderer.c_str(), ctx.info().version.c_str());
    // Which copies an installed or moved tree runs with (docs/scale-out.md#installing).
    std::fprintf(stderr, "marchstudio: shader dir %s\n", job.shader_dir.c_str());
    if (!writes_directly(image_format_for(output)))
      std::fprintf(stderr, "marchstudio: image module %s\n", image_backend_path().c_str());
    if (!in.shadertoy)
      std::fprintf(stderr, "marchstudio: shader %s (%s)\n", specialization_name(p.opts.specialize),
                   describe(scene_features(scene, p.opts)).c_str());
  }
  const StillTiling tiling = plan_render_tiling(in, fp, gpu_targets, job.tile_still, gl_max_width(ctx.info()),
                                                gl_max_height(ctx.info()));
  if (!tiling.tiled()) check_frame_size(ctx.info(), fp.width, fp.height, aovs ? 6 : 2);
  check_compute_input(job.dispatch, in, tiling.tiled());  // before anything is drawn or written

  // Programs whose assembled text an earlier job of the session compiled
  // are reused: the same text links to the same program.
  const long compiled_before = session.cache.misses(), reused_before = session.cache.hits();
  PassGraph graph(in.passes, &session.cache);
  const std::shared_ptr<const Program> post_prog = session.cache.get(fullscreen_vertex_source(), p.post_src);
  // --dispatch compute: the same scene shader as a compute pass, compiled once (render/compute_frame.h).
  std::optional<ComputeStill> compute;
  if (job.dispatch == Dispatch::compute) compute.emplace(ctx, graph, job.compute_group.value_or(ComputeGroup{}));
  const double t_compile = clock.lap();
  if (job.verbose)
    std::fprintf(stderr, "marchstudio: programs: %ld compiled, %ld from the cache\n",
                 session.cache.misses() - compiled_before, session.cache.hits() - reused_before);
  report_input_warnings(unbound_warnings(graph), input.string(), job.strict);
  if (!in.shadertoy)  // does [bounds] hold what map() draws? Before anything is written (cli/bounds_report.h)
    session.bounds.check(input.string(), posed, p.opts, [&](const Program& prog) {
      set_scene_uniforms(prog, posed, fp.width, fp.height, time, frame);
    }, job.strict);
  const std::unique_ptr<BloomStage> bloom = make_bloom_stage(in, p.display, p.opts, session.cache);
  fp.bloom = bloom.get();
  FrameRenderer renderer(ctx);
  StillFrame still;
  still.in.scene = &posed;
  still.in.time = time;
  still.in.frame = frame;
  std::copy(std::begin(scene.shadertoy.mouse), std::end(scene.shadertoy.mouse), still.in.mouse);
  still.fps = fps;
  still.params = fp;
  // The NaN/Inf guard: pixels with NaN/Inf in any channel read back
  // (colour, AOVs), and those a Shadertoy Image pass flagged, counted over
  // everything before the file is made.
  const auto check_nonfinite = [&](long long nonfinite) {
    if (nonfinite <= 0) return;
    const std::string what = std::to_string(nonfinite) + " of " +
                             std::to_string(static_cast<long long>(fp.width) * fp.height) +
                             " pixels have NaN/Inf values";
    if (job.strict) throw Error({Exit::threshold, input.string(), 0, "--strict", what + "; nothing written", {}, {}});
    std::fprintf(stderr, "marchstudio: %s: warning: %s (--strict makes this an error)\n", input.string().c_str(),
                 what.c_str());
  };
  ImageMetadata meta{{"Software", kSoftware},
                     {"ImageDescription", input.filename().string() + " t=" + std::to_string(time) +
                                              " spp=" + std::to_string(fp.spp)}};
  add_fingerprint(meta, frame_fingerprint(job_fingerprint(in, fp, p.post_src, job.aov_channels, scene.shadertoy.fps),
                                          frame, time));
  // auto: the probe's or the cache's choice for this device (cli/dispatch_probe.h), made with the bloom stage in place.
  if (job.dispatch == Dispatch::automatic)
    if (const DispatchChoice c = choose_dispatch(job.dispatch, graph, *post_prog, still, ctx, job.compute_group, job.verbose);
        c.dispatch == Dispatch::compute)
      compute.emplace(ctx, graph, c.group);
  if (tiling.tiled()) {  // rendered and written band by band
    StillFn draw_tile;
    if (compute) draw_tile = [&](const StillFrame& piece) { return compute->render(graph, *post_prog, piece); };
    render_tiled_file({output, job.aov_channels, meta, watchdog ? &*watchdog : nullptr, &deadline, check_nonfinite,
                       draw_tile},
                      renderer, graph, *post_prog, still, tiling);
    if (job.verbose)
      std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render and write %.1f ms (tiles of %dx%d)\n",
                   t_context * 1e3, t_compile * 1e3, clock.lap() * 1e3, tiling.tile_width, tiling.band_height);
    return;
  }
  Still out = compute ? compute->render(graph, *post_prog, still) : render_still(renderer, graph, *post_prog, still);
  Image img = std::move(out.color);
  check_nonfinite(count_nonfinite_pixels(img, aovs ? &out.aovs : nullptr) + out.flagged);
  if (aovs) img = append_channels(img, select_channels(out.aovs, job.aov_channels));
  const double t_render = clock.lap();
  deadline.check("the render");
  if (watchdog) watchdog->disarm();  // the write is atomic and must not be cut short
  {
    const RemoveTempOnSignal on_signal(output);  // Ctrl-C or SIGTERM while writing: no temporary left
    write_image(img, output, meta);
  }
  if (job.verbose)
    std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render %.1f ms, write %.1f ms\n",
                 t_context * 1e3, t_compile * 1e3, t_render * 1e3, clock.lap() * 1e3);
}

}  // namespace ms
