#include "pipeline/sequence.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>
#include <thread>

#include "core/clock.h"
#include "core/deadline.h"
#include "core/error.h"
#include "core/signal_scope.h"
#include "io/direct_codec.h"
#include "io/frame_writer.h"
#include "io/image_backend.h"
#include "io/image_io.h"
#include "io/video.h"
#include "pipeline/dispatch_probe.h"
#include "pipeline/fingerprint.h"
#include "pipeline/frame_session.h"
#include "pipeline/guarded_job.h"
#include "pipeline/nonfinite.h"
#include "pipeline/prepare.h"
#include "pipeline/progress.h"
#include "pipeline/sequence_state.h"
#include "render/aov.h"
#include "render/tiles.h"
#include "render/uniforms.h"
#include "scene/animation.h"
#include "scene/graph_animation.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

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

// Everything decided before the context: the prepared frame, what this
// run renders, and how a rerun recognises its frames.
struct SequencePlan {
  PreparedFrame p;
  double fps = kSceneFps;
  int writers = 1;
  std::vector<int> mine;  // this shard's frames
  std::string job_fp;     // what makes every frame (pipeline/fingerprint.h)
  ResumeScan scan;
  StatefulPlan sp;

  // The frame's time exactly as the shader gets it (a float); the pose uses
  // the same value, so a sequence frame equals `render --time` of it.
  float time(int f) const { return static_cast<float>(static_cast<double>(f) / fps); }
  std::string fingerprint(int f) const { return frame_fingerprint(job_fp, f, time(f)); }
  FrameInputs inputs(int f, const Scene& posed) const {
    FrameInputs fi;
    fi.scene = &posed;
    fi.time = time(f);
    fi.time_delta = static_cast<float>(1.0 / fps);
    fi.frame = f;
    std::copy(std::begin(p.in.scene.shadertoy.mouse), std::end(p.in.scene.shadertoy.mouse), fi.mouse);
    return fi;
  }
};

// Loads and checks everything, then sorts this shard's frames into done and to do.
SequencePlan plan_sequence(const SequenceJob& job, bool display) {
  const FrameJob& fj = job.frame;
  SequencePlan plan;
  plan.p = prepare(fj, display);
  LoadedInput& in = plan.p.in;
  plan.fps = fj.fps.value_or(in.shadertoy ? in.scene.shadertoy.fps : kSceneFps);  // Shadertoy runs at 60
  in.scene.shadertoy.fps = plan.fps;
  const FrameParams& fp = plan.p.fp;
  report_input_warnings(in.warnings, fj.input.string(), fj.strict);
  check_compute_input(fj.dispatch, in);  // before the context, as render refuses it
  const bool stateful = in.stateful();
  if (stateful && job.shard.count > 1 && job.mode == ShardMode::stride)
    fail_input("a shader with buffers carries its state from frame to frame: stride shards would each replay the "
               "whole sequence",
               fj.input.string(), 0, "--shard-mode",
               "use --shard-mode chunk: each shard replays only the frames before its chunk");
  // One writer keeps a stateful sequence's frames and checkpoints in order.
  plan.writers = stateful ? 1 : writer_threads();
  // The frame in flight and those waiting for the writers are alive at once,
  // and each buffer's two textures.
  check_frame_memory(frame_memory(fp.width, fp.height, frame_targets(fp.aovs) + buffer_targets(in), fp.aovs,
                                  1 + static_cast<int>(kQueuedFrames) + plan.writers),
                     fp.width, fp.height);
  plan.mine = shard_frames(job.range, job.shard, job.mode);
  for (int f : plan.mine) animated(in.scene, plan.time(f));  // throws on a pose that cannot render

  // What makes each frame: a rerun keeps only frames with the same fingerprint.
  plan.job_fp = job_fingerprint(in, fp, plan.p.post_src, fj.aov_channels, plan.fps);
  const FrameFingerprint fingerprint = [&plan](int f) { return plan.fingerprint(f); };
  const FramePattern& pattern = job.pattern;
  plan.scan = job.no_write ? ResumeScan{plan.mine, {}, {}, {}, {}}
                           : scan_existing(pattern, plan.mine, fp.width, fp.height, fingerprint, job.force);
  if (!stateful) return plan;
  StatefulPlan& sp = plan.sp;
  sp = plan_stateful(plan.mine, pattern, fp.width, fp.height, state_key(plan.job_fp), fingerprint,
                     job.no_write || job.force);
  if (!job.no_write) remove_checkpoint_temps(pattern, plan.mine, sp.key);
  // Read now, before the context: a checkpoint that cannot be used costs a replay, not the run.
  load_resume_state(sp, plan.mine, pattern, state_buffers(in.passes), fp.width, fp.height, fingerprint);
  // Frames after the resume point render again even when present: they follow from it.
  ResumeScan& scan = plan.scan;
  scan.todo = sp.todo;
  scan.skipped.erase(std::remove_if(scan.skipped.begin(), scan.skipped.end(),
                                    [&](const auto& s) { return s.first > sp.resume_from; }),
                     scan.skipped.end());
  scan.redone.clear();
  scan.stale.clear();
  scan.unmarked.clear();
  return plan;
}

// What the scan found, before the first frame.
void announce(const SequenceJob& job, const SequencePlan& plan, Progress& progress) {
  const ResumeScan& scan = plan.scan;
  for (const auto& [f, p] : scan.skipped) progress.skipped(f, p);
  for (const auto& [f, why] : scan.redone) progress.redo(f, job.pattern.path(f).string(), why);
  const std::size_t foreign = scan.stale.size() + scan.unmarked.size();
  if (foreign > 0)
    progress.line(std::to_string(foreign) + (foreign == 1 ? " frame on disk is" : " frames on disk are") +
                  " not this run's (" + std::to_string(scan.stale.size()) + " made from other inputs or settings, " +
                  std::to_string(scan.unmarked.size()) + " with no fingerprint): rendering them again");
  if (!scan.skipped.empty() || plan.mine.size() != static_cast<std::size_t>(job.range.count()))
    progress.line("shard " + std::to_string(job.shard.index) + "/" + std::to_string(job.shard.count) + ": " +
                  std::to_string(plan.mine.size()) + " of " + std::to_string(job.range.count()) + " frames, " +
                  std::to_string(scan.skipped.size()) + " already complete, " + std::to_string(scan.todo.size()) +
                  " to render");
}

// A stateful graph's buffers before the first frame to render: the
// checkpoint's, or frames 0..replay_until-1 drawn again, buffers only.
void restore_state(const SequenceJob& job, SequencePlan& plan, FrameSession& session, Progress& progress) {
  StatefulPlan& sp = plan.sp;
  PassGraph& graph = session.graph();
  if (sp.resume_from >= 0) {
    if (graph.buffers() != state_buffers(plan.p.in.passes))
      fail_system("internal: the graph's buffers are not those its checkpoint was read for",
                  checkpoint_path(job.pattern.path(sp.resume_from), sp.key).string());
    graph.reset();
    for (const auto& [b, img] : sp.state) graph.write_buffer(b, img);
    sp.state.clear();
    progress.line("resuming after frame " + std::to_string(sp.resume_from) + " from its checkpoint");
    return;
  }
  graph.reset();
  if (sp.replay_until > 0)
    progress.line("replaying frames 0.." + std::to_string(sp.replay_until - 1) +
                  " first: the buffers carry state from frame to frame");
  for (int n = 0; n < sp.replay_until; ++n) graph.step_buffers(plan.inputs(n, plan.p.in.scene), plan.p.fp);
}

// Times of the loop, for the summary line.
struct LoopTimes {
  double render = 0, wait = 0, loop = 0, writer_busy = 0;
  int stop_signal = 0;
};

// One frame drawn and read back, under its own --timeout; the image with
// its AOV channels and the NaN/Inf pixels counted.
Image draw_frame(const SequenceJob& job, SequencePlan& plan, FrameSession& session, int f, const Scene& posed,
                 GuardedJob& guard, FrameWriter& writer, long long& nonfinite) {
  const FrameJob& fj = job.frame;
  FrameParams& fp = plan.p.fp;
  // A frame that never finishes ends the run, but the frames already
  // handed to the writers are written first (also by the watchdog).
  guard.restart("frame " + std::to_string(f), [&writer] { writer.finish(); });
  fp.deadline = guard.limit();
  fp.exposure = posed.render.exposure;
  Image img;
  try {
    session.submit(plan.inputs(f, posed), fp);
    Still still = session.read(fp.aovs);
    img = std::move(still.color);
    nonfinite = count_nonfinite_pixels(img, fp.aovs ? &still.aovs : nullptr) + still.flagged;
    if (fp.aovs) img = append_channels(img, select_channels(still.aovs, fj.aov_channels));
  } catch (const Error& e) {
    guard.disarm();  // its hook names `writer`, which unwinding destroys
    fp.deadline = nullptr;
    if (e.info().key == "--timeout") fail_timeout("frame " + std::to_string(f), fj.timeout);
    throw;
  } catch (...) {
    guard.disarm();
    fp.deadline = nullptr;
    throw;
  }
  fp.deadline = nullptr;
  guard.finish();  // past the frame's deadline: the timeout error, the frame not written
  return img;
}

// A graph whose nodes move: this frame's shape into the session's field,
// prepared once for the frame; no shader compiles (the values are buffers).
void reshape_graph(FrameSession& session, const Scene& posed, const AssembleOptions& opts, int frame, bool verbose) {
  const long before = session.cache().misses();
  const GraphParts shape = graph_parts(posed, opts);
  const int compiled = session.job().reshape(shape);
  if (verbose)
    std::fprintf(stderr, "marchstudio: frame %d: graph posed, %ld programs compiled, pruning %.1f ms (%zu of %zu cells)\n",
                 frame, session.cache().misses() - before + compiled, session.job().field()->build_ms(),
                 session.job().field()->pruned_cells(), session.job().field()->cells());
}

// The frames to render, drawn and handed to the writers in order.
LoopTimes draw_frames(const SequenceJob& job, SequencePlan& plan, Progress& progress, const StopSignals& signals,
                      GuardedJob& guard) {
  const FrameJob& fj = job.frame;
  const std::vector<int>& todo = plan.scan.todo;
  const LoadedInput& in = plan.p.in;
  FrameParams& fp = plan.p.fp;
  LoopTimes t;
  FrameSession session;
  const Context& ctx = session.context(fj.backend);
  // A TIFF or JPEG needs the image module (PNG and EXR do not: io/direct_codec.h):
  // it loads while the shaders compile and the frame renders, not before the
  // context, whose driver dlopen would wait for it (io/image_backend.h).
  if (!writes_directly(image_format_for(job.pattern.path(job.range.first)))) preload_image_backend();
  if (fj.verbose)
    std::fprintf(stderr, "marchstudio: backend %s, GL_RENDERER %s\n", ctx.backend().c_str(), ctx.info().renderer.c_str());
  check_frame_size(ctx.info(), fp.width, fp.height, frame_targets(fp.aovs));
  session.load(plan.p);
  report_input_warnings(unbound_warnings(session.graph()), fj.input.string(), fj.strict);
  // The fragment pass or the compute dispatch (auto: pipeline/dispatch_probe.h), for every frame.
  const Scene first_pose = animated(in.scene, plan.time(todo.front()));
  session.choose(fj.dispatch, fj.compute_group, StillFrame{plan.inputs(todo.front(), first_pose), fp, plan.fps},
                 fj.verbose);
  const bool stateful = in.stateful();
  if (stateful) restore_state(job, plan, session, progress);
  // Paths on stdout as each frame lands, like `render` prints its one path.
  FrameWriter writer(
      kQueuedFrames,
      [](const WriteJob& w, double) {
        std::printf("%s\n", w.path.string().c_str());
        std::fflush(stdout);
      },
      {}, plan.writers);
  const StatefulPlan& sp = plan.sp;
  fs::path previous_state = sp.resume_from >= 0 ? checkpoint_path(job.pattern.path(sp.resume_from), sp.key) : fs::path{};
  progress.start();
  const Clock::time_point loop_start = Clock::now();
  guard.check();  // still loading and compiling's budget
  const NonfiniteGuard guard_base{fj.input.string(), fj.strict, {}, "it is not written"};
  for (int f : todo) {
    if ((t.stop_signal = signals.signal()) != 0) break;
    const float time = plan.time(f);
    const Scene posed = animated(in.scene, time);
    if (animates_graph(in.scene)) reshape_graph(session, posed, plan.p.opts, f, fj.verbose);
    if (!in.shadertoy) {  // [bounds] at this frame's pose: warned once; --strict stops here (pipeline/bounds_report.h)
      try {
        session.bounds().check(fj.input.string(), posed, plan.p.opts, [&](const Program& prog) {
          set_scene_uniforms(prog, posed, fp.width, fp.height, time, f);
        }, fj.strict);
      } catch (const Error&) {
        writer.finish();  // the frames before it are good: written, so a rerun resumes after them
        throw;
      }
    }
    const Clock::time_point t0 = Clock::now();
    long long nonfinite = 0;  // the NaN/Inf guard (pipeline/nonfinite.h)
    Image img = draw_frame(job, plan, session, f, posed, guard, writer, nonfinite);
    if (nonfinite > 0 && fj.strict) writer.finish();  // the frames before it are good: written, so a rerun resumes after them
    NonfiniteGuard guard = guard_base;
    guard.where = "frame " + std::to_string(f);
    guard_nonfinite(guard, nonfinite, static_cast<long long>(fp.width) * fp.height);
    const double took = seconds_since(t0);
    t.render += took;
    progress.rendered(f, took);
    if (job.no_write) continue;
    WriteJob w{f, std::move(img), job.pattern.path(f), frame_metadata(fj.input, time, fp.spp, plan.fingerprint(f), f),
               {}, {}, {}};
    if (stateful) {
      for (int b : session.graph().buffers()) w.state.emplace_back(b, session.graph().read_buffer(b));
      w.state_path = checkpoint_path(w.path, sp.key);
      w.drop = previous_state;
      previous_state = w.state_path;
      remove_checkpoints(w.path, w.state_path);  // a stale key's, from another shader or size
    }
    t.wait += writer.push(std::move(w));
  }
  guard.disarm();
  writer.finish();
  t.loop = seconds_since(loop_start);
  t.writer_busy = writer.busy_seconds();
  return t;
}

}  // namespace

int render_sequence(const SequenceJob& job) {
  const FrameJob& fj = job.frame;
  const bool display = is_display_format(image_format_for(job.pattern.path(job.range.first)));
  // --timeout: loading and compiling get one budget, then each frame its own.
  GuardedJob guard(fj.timeout, "loading and compiling");
  SequencePlan plan = plan_sequence(job, display);
  Progress progress(static_cast<int>(plan.scan.todo.size()), ::isatty(2) == 1);
  announce(job, plan, progress);

  LoopTimes t;
  // From here to the end, encoding included: Ctrl-C and SIGTERM stop cleanly.
  StopSignals signals;
  if (!plan.scan.todo.empty()) t = draw_frames(job, plan, progress, signals, guard);
  guard.disarm();
  progress.finish();
  const int done = progress.done();
  char summary[256];
  std::snprintf(summary, sizeof summary,
                "%d frames in %.2f s (%.2f frames/s): rendering %.2f s, waiting for the writer %.2f s, writer busy "
                "%.2f s; %zu skipped",
                done, t.loop, t.loop > 0 ? done / t.loop : 0.0, t.render, t.wait, t.writer_busy,
                plan.scan.skipped.size());
  progress.line(summary);
  const auto stopped = [&](int sig) {
    progress.line(std::string("stopped by ") + (sig == SIGINT ? "SIGINT" : "SIGTERM") +
                  ": the frames rendered so far are written; run the same command again to render the rest");
    return 128 + sig;
  };
  if (t.stop_signal != 0) return stopped(t.stop_signal);
  if (job.video.empty()) return 0;
  for (const fs::path& p : remove_stale_video_temps(job.video))
    std::fprintf(stderr, "marchstudio: removed %s, left by an interrupted encode\n", p.string().c_str());
  // The encoding gets one --timeout of its own, as each frame does.
  VideoJob v{job.ffmpeg, job.pattern.text(), job.range.first, plan.fps, job.video,
             Deadline::after(fj.timeout), [&signals] { return signals.signal(); }, job.range.count()};
  if (!encode_video(v)) return stopped(signals.signal());
  std::printf("%s\n", job.video.c_str());
  return 0;
}

}  // namespace ms
