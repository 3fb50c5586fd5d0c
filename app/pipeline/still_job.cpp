#include "pipeline/still_job.h"

#include <chrono>
#include <climits>
#include <cstdio>
#include <optional>

#include "core/clock.h"
#include "core/error.h"
#include "io/direct_codec.h"
#include "io/image_backend.h"
#include "io/image_io.h"
#include "io/stored_pixels.h"
#include "io/temp_cleanup.h"
#include "pipeline/dispatch_probe.h"
#include "pipeline/fingerprint.h"
#include "pipeline/guarded_job.h"
#include "pipeline/nonfinite.h"
#include "pipeline/prepare.h"
#include "pipeline/tiled_render.h"
#include "render/aov.h"
#include "render/compute_frame.h"
#include "render/frame.h"
#include "render/graph.h"
#include "render/still.h"
#include "render/uniforms.h"
#include "scene/animation.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// The time, frame rate and frame number a still draws at. The frame a
// sequence at this fps draws at `time`, as Shadertoy at 1 s has drawn 60:
// a scene's fps is --fps's default, a shader's its own.
struct StillClock {
  float time = 0;
  double fps = kSceneFps;
  int frame = 0;
};

StillClock still_clock(const FrameJob& job, const LoadedInput& in) {
  const Scene& scene = in.scene;
  StillClock c;
  c.time = job.time ? *job.time : scene.render.time;
  c.fps = still_fps(job, in);
  c.frame = job.frame.value_or(still_frame_number(c.time, c.fps));
  if (in.stateful() && c.frame != still_frame_number(c.time, c.fps))
    fail_input("--frame " + std::to_string(c.frame) + " conflicts with a shader that has buffers: its still replays "
                   "frames 0..N, N = round(time x fps) = " + std::to_string(still_frame_number(c.time, c.fps)),
               {}, 0, "--frame", "give --time (and --fps) instead");
  return c;
}

// -v: what the job runs with, once its context exists.
void say_setup(const FrameJob& job, const PreparedFrame& p, const Context& ctx, bool fresh_context) {
  if (fresh_context)
    std::fprintf(stderr, "marchstudio: backend %s, GL_RENDERER %s, GL_VERSION %s\n", ctx.backend().c_str(),
                 ctx.info().renderer.c_str(), ctx.info().version.c_str());
  // Which copies an installed or moved tree runs with (docs/scale-out.md#installing).
  std::fprintf(stderr, "marchstudio: shader dir %s\n", job.shader_dir.c_str());
  if (!writes_directly(image_format_for(job.output)))
    std::fprintf(stderr, "marchstudio: image module %s\n", image_backend_path().c_str());
  if (!p.in.shadertoy)
    std::fprintf(stderr, "marchstudio: shader %s (%s)\n", specialization_name(p.opts.specialize),
                 describe(scene_features(p.in.scene, p.opts)).c_str());
}

}  // namespace

void say_removed_temps(const std::vector<fs::path>& outputs) {
  for (const fs::path& t : remove_dead_temps(outputs))
    std::fprintf(stderr, "marchstudio: removed %s, left by an interrupted run\n", t.string().c_str());
}

void print_job_shader(const FrameJob& job) {
  const PreparedFrame p = prepare(job, is_display_format(image_format_for(job.output)));
  for (const PassSource& pass : p.in.passes) {
    if (p.in.passes.size() > 1) std::printf("// ==== marchstudio: pass %s ====\n", comment_label(pass.name).c_str());
    std::fputs(pass.source.text.c_str(), stdout);
  }
}

void render_still_job(const FrameJob& job, FrameSession& session) {
  // From here on the image has job.timeout seconds; the watchdog ends the
  // process if a draw (or the driver's compile) never returns.
  GuardedJob guard(job.timeout, "the render");
  const fs::path& input = job.input;
  const fs::path& output = job.output;
  const bool aovs = job.aovs();
  PreparedFrame p = prepare(job, is_display_format(image_format_for(output)));
  const LoadedInput& in = p.in;
  FrameParams& fp = p.fp;
  const StillClock when = still_clock(job, in);
  report_input_warnings(in.warnings, input.string(), job.strict);
  fp.deadline = guard.limit();
  // Before the (slow) context: past the memory budget a still is drawn in
  // tiles (pipeline/tiled_render.h), and one with buffers is refused.
  const int gpu_targets = frame_targets(aovs) + buffer_targets(in);
  plan_render_tiling(in, fp, gpu_targets, job.tile_still, INT_MAX, INT_MAX);
  const Scene posed = animated(in.scene, when.time);  // [[animation]] keyframes at this time
  fp.exposure = posed.render.exposure;

  Stopwatch clock;
  const bool fresh_context = !session.has_context();
  Context& ctx = session.context(job.backend);
  // A TIFF or JPEG needs the image module (PNG and EXR do not: io/direct_codec.h):
  // it loads while the shaders compile and the frame renders, not before the
  // context, whose driver dlopen would wait for it (io/image_backend.h).
  if (!writes_directly(image_format_for(output)) && !job.image_out) preload_image_backend();
  const double t_context = clock.lap();
  if (job.verbose) say_setup(job, p, ctx, fresh_context);
  const StillTiling tiling = plan_render_tiling(in, fp, gpu_targets, job.tile_still, gl_max_width(ctx.info()),
                                                gl_max_height(ctx.info()));
  if (!tiling.tiled()) check_frame_size(ctx.info(), fp.width, fp.height, frame_targets(aovs));
  else if (job.image_out)
    fail_input("a " + std::to_string(fp.width) + "x" + std::to_string(fp.height) +
                   " still is drawn in tiles, too large to hand back in memory",
               input.string(), 0, "size", "render it to a file");
  check_compute_input(job.dispatch, in);  // before anything is drawn or written

  const long compiled_before = session.cache().misses(), reused_before = session.cache().hits();
  session.load(p);
  StillFrame still;
  still.in.scene = &posed;
  still.in.time = when.time;
  still.in.frame = when.frame;
  std::copy(std::begin(in.scene.shadertoy.mouse), std::end(in.scene.shadertoy.mouse), still.in.mouse);
  still.fps = when.fps;
  still.params = fp;
  // --dispatch compute: the same scene shader as a compute pass, compiled once (render/compute_frame.h).
  if (job.dispatch != Dispatch::automatic) session.choose(job.dispatch, job.compute_group, still, job.verbose);
  const double t_compile = clock.lap();
  if (job.verbose) {
    std::fprintf(stderr, "marchstudio: programs: %ld compiled, %ld from the cache\n",
                 session.cache().misses() - compiled_before, session.cache().hits() - reused_before);
    if (const GraphField* f = session.job().field(); f && !f->summary().empty())
      std::fprintf(stderr, "marchstudio: graph: %s\n", f->summary().c_str());
  }
  report_input_warnings(unbound_warnings(session.graph()), input.string(), job.strict);
  if (!in.shadertoy)  // does [bounds] hold what map() draws? Before anything is written (pipeline/bounds_report.h)
    session.bounds().check(input.string(), posed, p.opts, [&](const Program& prog) {
      set_scene_uniforms(prog, posed, fp.width, fp.height, when.time, when.frame);
    }, job.strict);
  const NonfiniteGuard nonfinite{input.string(), job.strict, {}, "nothing written"};
  const ImageMetadata meta =
      frame_metadata(input, when.time, fp.spp,
                     frame_fingerprint(job_fingerprint(in, fp, p.post_src, job.aov_channels, in.scene.shadertoy.fps),
                                       when.frame, when.time));
  // auto: the probe's or the cache's choice for this device (pipeline/dispatch_probe.h).
  if (job.dispatch == Dispatch::automatic) session.choose(job.dispatch, job.compute_group, still, job.verbose);
  if (tiling.tiled()) {  // rendered and written band by band
    render_tiled_file({output, job.aov_channels, meta, guard.watchdog(), &guard.deadline(), nonfinite}, session,
                      still, tiling);
    if (job.verbose)
      std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render and write %.1f ms (tiles of %dx%d)\n",
                   t_context * 1e3, t_compile * 1e3, clock.lap() * 1e3, tiling.tile_width, tiling.band_height);
    return;
  }
  Still out = session.draw(still);
  Image img = std::move(out.color);
  guard_nonfinite(nonfinite, count_nonfinite_pixels(img, aovs ? &out.aovs : nullptr) + out.flagged,
                  static_cast<long long>(fp.width) * fp.height);
  if (aovs) img = append_channels(img, select_channels(out.aovs, job.aov_channels));
  const double t_render = clock.lap();
  guard.finish();  // the write is atomic and must not be cut short
  if (job.image_out) {
    *job.image_out = stored_pixels(img, image_format_for(output));
    return;
  }
  {
    const RemoveTempOnSignal on_signal(output);  // Ctrl-C or SIGTERM while writing: no temporary left
    write_image(img, output, meta);
  }
  if (job.verbose)
    std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render %.1f ms, write %.1f ms\n",
                 t_context * 1e3, t_compile * 1e3, t_render * 1e3, clock.lap() * 1e3);
}

}  // namespace ms
