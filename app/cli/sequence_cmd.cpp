#include "cli/sequence_cmd.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <optional>
#include <regex>
#include <thread>

#include "bench/bench.h"
#include "cli/bloom_setup.h"
#include "cli/bounds_report.h"
#include "cli/dispatch_flag.h"
#include "cli/dispatch_probe.h"
#include "cli/input.h"
#include "cli/progress.h"
#include "cli/render_cmd.h"
#include "cli/shader_dir.h"
#include "core/error.h"
#include "core/signal_scope.h"
#include "core/version.h"
#include "gl/context.h"
#include "io/frame_writer.h"
#include "io/direct_codec.h"
#include "io/image_backend.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "io/video.h"
#include "render/aov.h"
#include "core/deadline.h"
#include "render/frame.h"
#include "render/tiles.h"
#include "render/graph.h"
#include "render/scene_drawer.h"
#include "render/still.h"
#include "render/uniforms.h"
#include "cli/fingerprint.h"
#include "cli/sequence_state.h"
#include "scene/animation.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

constexpr double kDefaultFps = kSceneFps;
// Frames waiting for the writer: enough to ride out a slow write, small
// enough that 4 float frames stay modest (640x360: 15 MB; 4K: 530 MB).
constexpr std::size_t kQueuedFrames = 4;

// The process's one piece of global state: a signal handler can only set a
// flag. SIGINT (Ctrl-C) and SIGTERM (what Slurm's scancel and time limit
// send first) stop the loop after the frame in flight; the frames already
// rendered are still written. SA_RESETHAND: a second signal kills at once.
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void on_stop_signal(int sig) { g_stop_signal = sig; }

class StopSignals {
 public:
  StopSignals() : scope_(on_stop_signal, SA_RESETHAND) { g_stop_signal = 0; }
  int signal() const { return g_stop_signal; }

 private:
  SignalScope scope_;
};

// One writer per four cores, at most 4: on a small machine the renderer
// (llvmpipe) needs the cores; on a big one with a GPU, PNG encoding is the
// bottleneck and parallel writers keep up with it.
int writer_threads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return std::clamp(static_cast<int>(cores / 4), 1, 4);
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Everything decided from the flags before any file is read.
struct Plan {
  FrameRange range;
  Shard shard;
  ShardMode mode = ShardMode::stride;
  double fps = kDefaultFps;
  std::string pattern;
};

Plan plan_from_flags(const RenderArgs& a) {
  if (!a.frames)
    fail_input("--shard, --shard-mode, --video and --no-write need --frames", {}, 0, "--frames",
               "e.g. --frames 0..59 --fps 24 -o out/frame_%04d.png");
  if (a.time_set)
    fail_input("--time conflicts with --frames: each frame's time is frame / fps", {}, 0, "--time",
               "shift the animation with --frames instead");
  if (a.frame != 0) fail_input("--frame conflicts with --frames", {}, 0, "--frame");
  if (a.spp < 0 || a.spp > 1024) fail_input("--spp must be in 1..1024", {}, 0, "--spp");
  Plan p;
  p.range = *a.frames;
  p.fps = a.fps_set ? a.fps : kDefaultFps;
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
  // Flags, output pattern, ffmpeg, scene, shaders and every frame's pose are
  // checked before the GL context exists: bad input never leaves a file.
  Plan plan = plan_from_flags(a);
  const FramePattern pattern(plan.pattern);
  check_output_path(pattern.path(plan.range.first));
  const bool display = is_display_format(image_format_for(pattern.path(plan.range.first)));
  const bool aovs = !a.aov.empty();
  const std::vector<std::string> aov_names = aovs ? aov_channels(a.aov) : std::vector<std::string>{};
  if (aovs && display) fail_input("--aov needs an .exr output pattern", plan.pattern, 0, "--aov");
  fs::path ffmpeg;
  if (!a.video.empty()) {
    if (!display) fail_input("--video needs PNG, JPEG or TIFF frames, not EXR", plan.pattern, 0, "--video");
    ffmpeg = find_on_path("ffmpeg");
    if (ffmpeg.empty())
      throw Error(ErrorInfo{Exit::system, {}, 0, "--video", "ffmpeg is not installed (not found on PATH)",
                            "install it (Debian: apt-get install ffmpeg), or drop --video and encode the frames later", {}});
  }

  // --timeout: loading and compiling get one budget, then each frame its own.
  Deadline deadline = Deadline::after(a.timeout);
  std::optional<Watchdog> watchdog;
  if (deadline.limited()) watchdog.emplace().arm(deadline, "loading and compiling");
  // Animated values stay uniforms in a folded shader: one program serves every frame.
  AssembleOptions opts = assemble_options(a.shader_dir, a.allow_include, a.no_specialize, a.overrides.uniforms);
  opts.defines = a.defines;
  if (aovs)
    for (const auto& d : aov_defines()) opts.defines.push_back(d);
  LoadedInput in = load_input_scene(a.input, a.disable, a.preset, a.overrides.set);
  if (aovs && in.shadertoy) fail_input("--aov needs a scene, not a Shadertoy shader", a.input, 0, "--aov");
  apply_shadertoy_flags(in, a.shadertoy);
  if (in.shadertoy && !a.fps_set) plan.fps = in.scene.shadertoy.fps;  // Shadertoy runs at 60
  in.scene.shadertoy.fps = plan.fps;
  const Scene& scene = in.scene;
  FrameParams fp;
  fp.width = scene.render.width;
  fp.height = scene.render.height;
  if (a.size.width > 0) {
    fp.width = a.size.width;
    fp.height = a.size.height;
  }
  fp.spp = a.spp > 0 ? a.spp : scene.render.spp;
  fp.aovs = aovs;
  fp.tile_size = a.tile_size;
  in.scene.bloom.enabled = bloom_on(in, display);  // cli/bloom_setup.h
  fp.fused_post = fuse_post(in, fp.spp, aovs, display, opts);
  assemble_input(in, opts);
  report_input_warnings(in.warnings, a.input, a.strict);
  // --dispatch: refused here, before the context, as render refuses it (cli/dispatch_flag.h).
  const Dispatch requested = a.dispatch;
  const std::optional<ComputeGroup> group = a.compute_group;
  check_compute_input(requested, in, false);
  const bool stateful = in.stateful();
  if (stateful && plan.shard.count > 1 && plan.mode == ShardMode::stride)
    fail_input("a shader with buffers carries its state from frame to frame: stride shards would each replay the "
               "whole sequence",
               a.input, 0, "--shard-mode", "use --shard-mode chunk: each shard replays only the frames before its chunk");
  // One writer keeps a stateful sequence's frames and checkpoints in order.
  const int writers = stateful ? 1 : writer_threads();
  // The frame in flight and those waiting for the writers are alive at once,
  // and each buffer's two textures.
  check_frame_memory(frame_memory(fp.width, fp.height, (aovs ? 6 : 2) + 2 * (static_cast<int>(in.passes.size()) - 1),
                                  aovs, 1 + static_cast<int>(kQueuedFrames) + writers),
                     fp.width, fp.height);
  const ShaderSource post_src = assemble_post(scene.render.tonemap, display && !in.shadertoy, opts, in.shadertoy,
                                               scene.bloom.enabled);
  // The frame's time exactly as the shader gets it (a float); the pose uses
  // the same value, so a sequence frame equals `render --time` of it.
  const auto frame_time = [&](int f) { return static_cast<float>(static_cast<double>(f) / plan.fps); };
  const std::vector<int> mine = shard_frames(plan.range, plan.shard, plan.mode);
  for (int f : mine) animated(scene, frame_time(f));  // throws on a pose that cannot render

  // What makes each frame: a rerun keeps only frames with the same fingerprint.
  const std::string job = job_fingerprint(in, fp, post_src, aov_names, plan.fps);
  const FrameFingerprint fingerprint = [&](int f) { return frame_fingerprint(job, f, frame_time(f)); };
  ResumeScan scan = a.no_write ? ResumeScan{mine, {}, {}, {}, {}}
                               : scan_existing(pattern, mine, fp.width, fp.height, fingerprint, a.force);
  StatefulPlan sp;
  if (stateful) {
    sp = plan_stateful(mine, pattern, fp.width, fp.height, state_key(job), fingerprint, a.no_write || a.force);
    if (!a.no_write) remove_checkpoint_temps(pattern, mine, sp.key);
    // Read now, before the context: a checkpoint that cannot be used costs a replay, not the run.
    load_resume_state(sp, mine, pattern, state_buffers(in.passes), fp.width, fp.height, fingerprint);
    // Frames after the resume point render again even when present: they follow from it.
    scan.todo = sp.todo;
    scan.skipped.erase(std::remove_if(scan.skipped.begin(), scan.skipped.end(),
                                      [&](const auto& s) { return s.first > sp.resume_from; }),
                       scan.skipped.end());
    scan.redone.clear();
    scan.stale.clear();
    scan.unmarked.clear();
  }
  const std::vector<int>& todo = scan.todo;
  Progress progress(static_cast<int>(todo.size()), ::isatty(2) == 1);
  for (const auto& [f, p] : scan.skipped) progress.skipped(f, p);
  for (const auto& [f, why] : scan.redone) progress.redo(f, pattern.path(f).string(), why);
  if (!scan.stale.empty() || !scan.unmarked.empty())
    progress.line(std::to_string(scan.stale.size() + scan.unmarked.size()) +
                  (scan.stale.size() + scan.unmarked.size() == 1 ? " frame on disk is" : " frames on disk are") +
                  " not this run's (" +
                  std::to_string(scan.stale.size()) + " made from other inputs or settings, " +
                  std::to_string(scan.unmarked.size()) + " with no fingerprint): rendering them again");
  if (!scan.skipped.empty() || mine.size() != static_cast<std::size_t>(plan.range.count()))
    progress.line("shard " + std::to_string(plan.shard.index) + "/" + std::to_string(plan.shard.count) + ": " +
                  std::to_string(mine.size()) + " of " + std::to_string(plan.range.count()) + " frames, " +
                  std::to_string(scan.skipped.size()) + " already complete, " + std::to_string(todo.size()) +
                  " to render");

  int stop_signal = 0;
  double render_s = 0, wait_s = 0, loop_s = 0, writer_busy_s = 0;
  // From here to the end, encoding included: Ctrl-C and SIGTERM stop cleanly.
  StopSignals signals;
  if (!todo.empty()) {
    std::unique_ptr<Context> ctx = create_headless_context(a.backend);
    // A TIFF or JPEG needs the image module (PNG and EXR do not: io/direct_codec.h):
    // it loads while the shaders compile and the frame renders, not before the
    // context, whose driver dlopen would wait for it (io/image_backend.h).
    if (!writes_directly(image_format_for(pattern.path(plan.range.first)))) preload_image_backend();
    if (a.verbose)
      std::fprintf(stderr, "marchstudio: backend %s, GL_RENDERER %s\n", ctx->backend().c_str(),
                   ctx->info().renderer.c_str());
    check_frame_size(ctx->info(), fp.width, fp.height, aovs ? 6 : 2);
    PassGraph graph(in.passes);
    report_input_warnings(unbound_warnings(graph), a.input, a.strict);
    const Program post_prog(fullscreen_vertex_source(), post_src);
    ProgramCache bloom_programs;
    const std::unique_ptr<BloomStage> bloom = make_bloom_stage(in, display, opts, bloom_programs);
    fp.bloom = bloom.get();
    BoundsReport bounds;  // after the context: its probe program dies first
    const auto inputs_at = [&](int f, const Scene& posed) {
      FrameInputs fi;
      fi.scene = &posed;
      fi.time = frame_time(f);
      fi.time_delta = static_cast<float>(1.0 / plan.fps);
      fi.frame = f;
      std::copy(std::begin(scene.shadertoy.mouse), std::end(scene.shadertoy.mouse), fi.mouse);
      return fi;
    };
    // The fragment pass or the compute dispatch (auto: cli/dispatch_probe.h), for every frame.
    const Scene first_pose = animated(scene, frame_time(todo.front()));
    const StillFrame probe{inputs_at(todo.front(), first_pose), fp, plan.fps};
    const DispatchChoice choice = choose_dispatch(requested, graph, post_prog, probe, *ctx, group, a.verbose);
    SceneDrawer renderer(*ctx, graph, choice.dispatch, choice.group);
    if (stateful) {
      const std::vector<int> buffers = graph.buffers();
      if (sp.resume_from >= 0) {
        if (buffers != state_buffers(in.passes))
          fail_system("internal: the graph's buffers are not those its checkpoint was read for",
                      checkpoint_path(pattern.path(sp.resume_from), sp.key).string());
        graph.reset();
        for (const auto& [b, img] : sp.state) graph.write_buffer(b, img);
        sp.state.clear();
        progress.line("resuming after frame " + std::to_string(sp.resume_from) + " from its checkpoint");
      } else {
        graph.reset();
        if (sp.replay_until > 0)
          progress.line("replaying frames 0.." + std::to_string(sp.replay_until - 1) +
                        " first: the buffers carry state from frame to frame");
        for (int n = 0; n < sp.replay_until; ++n) graph.step_buffers(inputs_at(n, scene), fp);
      }
    }
    // Paths on stdout as each frame lands, like `render` prints its one path.
    FrameWriter writer(
        kQueuedFrames,
        [](const WriteJob& job, double) {
          std::printf("%s\n", job.path.string().c_str());
          std::fflush(stdout);
        },
        {}, writers);
    fs::path previous_state = sp.resume_from >= 0 ? checkpoint_path(pattern.path(sp.resume_from), sp.key) : fs::path{};
    progress.start();
    const auto loop_start = std::chrono::steady_clock::now();
    deadline.check("loading and compiling");
    for (int f : todo) {
      if ((stop_signal = signals.signal()) != 0) break;
      const float time = frame_time(f);
      const Scene posed = animated(scene, time);
      if (!in.shadertoy) {  // [bounds] at this frame's pose: warned once; --strict stops here (cli/bounds_report.h)
        try {
          bounds.check(a.input, posed, opts, [&](const Program& prog) {
            set_scene_uniforms(prog, posed, fp.width, fp.height, time, f);
          }, a.strict);
        } catch (const Error&) {
          writer.finish();  // the frames before it are good: written, so a rerun resumes after them
          throw;
        }
      }
      const auto t0 = std::chrono::steady_clock::now();
      // A frame that never finishes ends the run, but the frames already
      // handed to the writers are written first (also by the watchdog).
      deadline = Deadline::after(a.timeout);
      if (watchdog) watchdog->arm(deadline, "frame " + std::to_string(f), [&writer] { writer.finish(); });
      fp.deadline = deadline.limited() ? &deadline : nullptr;
      fp.exposure = posed.render.exposure;
      Image img;
      long long nonfinite = 0;  // the NaN/Inf guard, as in render_cmd.cpp
      try {
        renderer.draw(graph, post_prog, inputs_at(f, posed), fp);
        Still still = renderer.read(aovs);
        img = std::move(still.color);
        nonfinite = count_nonfinite_pixels(img, aovs ? &still.aovs : nullptr) + still.flagged;
        if (aovs) img = append_channels(img, select_channels(still.aovs, aov_names));
      } catch (const Error& e) {
        if (watchdog) watchdog->disarm();  // its hook names `writer`, which unwinding destroys
        if (e.info().key == "--timeout") fail_timeout("frame " + std::to_string(f), a.timeout);
        throw;
      } catch (...) {
        if (watchdog) watchdog->disarm();
        throw;
      }
      if (watchdog) watchdog->disarm();
      if (deadline.expired()) fail_timeout("frame " + std::to_string(f), a.timeout);
      if (nonfinite > 0) {
        const std::string what = "frame " + std::to_string(f) + ": " + std::to_string(nonfinite) + " of " +
                                 std::to_string(static_cast<long long>(fp.width) * fp.height) +
                                 " pixels have NaN/Inf values";
        if (a.strict) {
          writer.finish();  // the frames before it are good: written, so a rerun resumes after them
          throw Error({Exit::threshold, a.input, 0, "--strict", what + "; it is not written", {}, {}});
        }
        std::fprintf(stderr, "marchstudio: %s: warning: %s (--strict makes this an error)\n", a.input.c_str(),
                     what.c_str());
      }
      const double took = since(t0);
      render_s += took;
      progress.rendered(f, took);
      if (a.no_write) continue;
      ImageMetadata meta{{"Software", kSoftware},
                         {"ImageDescription", fs::path(a.input).filename().string() + " t=" + std::to_string(time) +
                                                  " spp=" + std::to_string(fp.spp) + " frame=" + std::to_string(f)}};
      add_fingerprint(meta, fingerprint(f));
      WriteJob job{f, std::move(img), pattern.path(f), std::move(meta), {}, {}, {}};
      if (stateful) {
        for (int b : graph.buffers()) job.state.emplace_back(b, graph.read_buffer(b));
        job.state_path = checkpoint_path(job.path, sp.key);
        job.drop = previous_state;
        previous_state = job.state_path;
        remove_checkpoints(job.path, job.state_path);  // a stale key's, from another shader or size
      }
      wait_s += writer.push(std::move(job));
    }
    if (watchdog) watchdog->disarm();
    writer.finish();
    loop_s = since(loop_start);
    writer_busy_s = writer.busy_seconds();
  }
  if (watchdog) watchdog->disarm();
  progress.finish();
  const int done = progress.done();
  char summary[256];
  std::snprintf(summary, sizeof summary,
                "%d frames in %.2f s (%.2f frames/s): rendering %.2f s, waiting for the writer %.2f s, writer busy "
                "%.2f s; %zu skipped",
                done, loop_s, loop_s > 0 ? done / loop_s : 0.0, render_s, wait_s, writer_busy_s, scan.skipped.size());
  progress.line(summary);
  const auto stopped = [&](int sig) {
    progress.line(std::string("stopped by ") + (sig == SIGINT ? "SIGINT" : "SIGTERM") +
                  ": the frames rendered so far are written; run the same command again to render the rest");
    return 128 + sig;
  };
  if (stop_signal != 0) return stopped(stop_signal);
  if (!a.video.empty()) {
    for (const fs::path& p : remove_stale_video_temps(a.video))
      std::fprintf(stderr, "marchstudio: removed %s, left by an interrupted encode\n", p.string().c_str());
    // The encoding gets one --timeout of its own, as each frame does.
    VideoJob job{ffmpeg, plan.pattern, plan.range.first, plan.fps, a.video, Deadline::after(a.timeout),
                 [&signals] { return signals.signal(); }, plan.range.count()};
    if (!encode_video(job)) return stopped(signals.signal());
    std::printf("%s\n", a.video.c_str());
  }
  return 0;
}

}  // namespace ms
