#include "bench/bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "core/clock.h"
#include "core/error.h"
#include "pipeline/nonfinite.h"
#include "render/frame.h"
#include "render/gpu_timer.h"
#include "render/uniforms.h"
#include "shader/assemble.h"

namespace ms {
namespace {



std::vector<double> channel(const Image& img, const std::string& name) {
  const auto it = std::find(img.channels.begin(), img.channels.end(), name);
  if (it == img.channels.end()) fail_system("bench: the counting pass has no '" + name + "' channel");
  const size_t c = static_cast<size_t>(it - img.channels.begin()), n = img.channels.size();
  std::vector<double> v(static_cast<size_t>(img.width) * img.height);
  for (size_t p = 0; p < v.size(); ++p) v[p] = img.pixels[p * n + c];
  return v;
}

double fraction_over_half(const std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const auto k = std::count_if(v.begin(), v.end(), [](double x) { return x > 0.5; });
  return static_cast<double>(k) / static_cast<double>(v.size());
}

}  // namespace

void check_bench_settings(const BenchSettings& s) {
  if (s.frames < 1 || s.frames > 100000) fail_input("--frames must be in 1..100000", {}, 0, "--frames");
  if (s.warmup < 0 || s.warmup > 100000) fail_input("--warmup must be in 0..100000", {}, 0, "--warmup");
  if (s.spp < 1 || s.spp > 1024) fail_input("--spp must be in 1..1024", {}, 0, "--spp");
}

BenchCost measure_cost(const Image& aovs) {
  BenchCost c;
  c.pixels = static_cast<long long>(aovs.width) * aovs.height;
  c.primary_steps = count_stats(channel(aovs, "steps"));
  c.shadow_steps = count_stats(channel(aovs, "shadow_steps"));
  c.reflection_steps = count_stats(channel(aovs, "reflection_steps"));
  c.sdf_evals = count_stats(channel(aovs, "sdf_evals"));
  c.step_cap_fraction = fraction_over_half(channel(aovs, "step_cap"));
  c.hit_fraction = fraction_over_half(channel(aovs, "hit"));
  return c;
}

void count_graph_cost(FramePrograms& job, const PreparedFrame& p, const Scene& posed, const BenchSettings& s,
                      AssembleOptions count_opts, BenchResult& r) {
  count_opts.defines.push_back({"MS_COST_PRIMS", "1"});
  FrameParams fp = p.fp;
  fp.width = s.width;
  fp.height = s.height;
  r.primitive_evals = count_frame_cost(job, assemble_scene(posed, count_opts), posed, s.time, fp).sdf_evals;
  const GraphField* f = job.field();
  r.graph_eval = !f ? "inline" : f->summary().empty() ? "interpreter" : "interpreter, pruned: " + f->summary();
  r.prune_ms = f ? f->build_ms() : 0.0;
}

BenchCost count_frame_cost(FramePrograms& job, const ShaderSource& counting, const Scene& posed, float time,
                           FrameParams fp) {
  fp.spp = 1;
  fp.aovs = true;
  fp.fused_post = false;
  const std::unique_ptr<Program> prog = job.program(counting);
  job.draw_program(*prog, [&](const Program& p) { set_scene_uniforms(p, posed, fp.width, fp.height, time, 0); }, fp);
  const Image aovs = job.read_aovs(), colour = job.read_color();
  BenchCost c = measure_cost(aovs);
  c.nonfinite_pixels = count_nonfinite_pixels(colour, &aovs);
  return c;
}

namespace {

// The inputs of bench's frames: a scene draws the same frame each time
// (uFrame 0); a stateful shader's frames follow on, at its fps.
struct FrameFeed {
  const Scene& scene;
  float time;
  double fps;
  bool stateful;
  int frame = 0;

  FrameInputs next() {
    FrameInputs in;
    in.scene = &scene;
    in.time = time;
    std::copy(std::begin(scene.shadertoy.mouse), std::end(scene.shadertoy.mouse), in.mouse);
    if (stateful) {
      in.frame = frame;
      in.time = time + static_cast<float>(frame / fps);
      in.time_delta = static_cast<float>(1.0 / fps);
      ++frame;
    }
    return in;
  }
};

// Startup: compile and link, then force the lazy code generation with a
// 1x1 frame, then the first full-size frame.
void time_startup(FrameSession& session, const PreparedFrame& p, const BenchSettings& s, const FrameParams& fp,
                  FrameFeed& feed, BenchResult& r, long long lookups0, long long sets0) {
  const Clock::time_point t0 = Clock::now();
  session.load(p);  // the graph, post pass and bloom stage, compiled now
  StillFrame probe{feed.next(), fp, feed.fps};
  feed.frame = 0;
  const DispatchChoice choice = session.choose(s.dispatch, s.group, probe, s.verbose);
  r.dispatch = session.job().dispatch();
  r.group = choice.group;
  r.link_ms = ms_since(t0);
  FrameParams tiny = fp;
  tiny.width = tiny.height = 1;
  tiny.spp = 1;
  session.submit(feed.next(), tiny);
  glFinish();
  r.compile_link_ms = ms_since(t0);
  feed.frame = 0;
  session.submit(feed.next(), fp);
  glFinish();
  r.first_frame_ms = ms_since(t0);
  r.lookups_first = Program::gl_lookups() - lookups0;
  r.sets_first = Program::gl_uniform_sets() - sets0;
}

// Timed frames: the GPU timer brackets exactly the draw; wall time adds
// the wait for completion (glFinish), which is what a user sees.
void time_frames(FrameSession& session, const BenchSettings& s, const FrameParams& fp, FrameFeed& feed,
                 BenchResult& r, long long lookups0) {
  for (int i = 0; i < s.warmup; ++i) session.submit(feed.next(), fp);
  glFinish();
  // Each timed frame of a multi-pass graph is followed by one timed pass by
  // pass, so the sum of the passes and the frame see the same machine load:
  // their ratio shows what running the passes as one graph adds, even on a
  // busy machine. A graph of one pass is its frame (the post pass goes with
  // the last pass): its pass time is the frame's wall time, and no second
  // frame is drawn, which halved bench's frames for every scene.
  PassGraph& graph = session.graph();
  const bool by_pass = graph.size() > 1;
  GpuTimer timer;
  std::vector<double> gpu, wall, submit;
  std::vector<std::vector<double>> per(graph.size());
  long long timed_sets = 0;
  for (int i = 0; i < s.frames; ++i) {
    const FrameInputs in = feed.next();
    const long long sets_before = Program::gl_uniform_sets();
    const Clock::time_point w0 = Clock::now();
    timer.begin();
    session.submit(in, fp);
    submit.push_back(ms_since(w0));
    timed_sets += Program::gl_uniform_sets() - sets_before;
    timer.end();
    glFinish();
    wall.push_back(ms_since(w0));
    gpu.push_back(timer.wait_ms());
    if (!by_pass) continue;
    graph.set_timing(true);
    session.submit(feed.next(), fp);
    graph.set_timing(false);
    for (size_t p = 0; p < graph.size(); ++p) per[p].push_back(graph.pass_ms()[p]);
  }
  if (!by_pass) per[0] = wall;
  r.gpu_timer = std::any_of(gpu.begin(), gpu.end(), [](double x) { return x > 0.0; });
  r.gpu_ms = summarize(gpu);
  r.wall_ms = summarize(wall);
  r.submit_ms = summarize(submit);
  r.lookups_later = Program::gl_lookups() - lookups0 - r.lookups_first;
  r.sets_per_timed_frame = static_cast<double>(timed_sets) / s.frames;
  for (size_t p = 0; p < graph.size(); ++p) r.passes.push_back({graph.name(p), summarize(per[p])});
}

}  // namespace

BenchResult run_bench(FrameSession& session, const PreparedFrame& p, const Scene& scene,
                      const ShaderSource* counting, const BenchSettings& s) {
  check_bench_settings(s);
  const Context& ctx = session.context();  // made by the caller, with its backend
  check_frame_size(ctx.info(), s.width, s.height, frame_targets(true));  // the counting pass's AOV targets
  BenchResult r;
  r.backend = ctx.backend();
  r.gl_renderer = ctx.info().renderer;
  r.gl_vendor = ctx.info().vendor;
  r.gl_version = ctx.info().version;

  FrameParams fp;
  fp.width = s.width;
  fp.height = s.height;
  fp.spp = s.spp;
  fp.exposure = scene.render.exposure;
  fp.fused_post = s.fused_post;
  FrameFeed feed{scene, s.time, scene.shadertoy.fps, p.in.stateful()};
  const long long lookups0 = Program::gl_lookups();  // a process-wide count: only bench's own frames
  const long long sets0 = Program::gl_uniform_sets();
  time_startup(session, p, s, fp, feed, r, lookups0, sets0);
  time_frames(session, s, fp, feed, r, lookups0);
  if (counting) {
    r.cost = count_frame_cost(session.job(), *counting, scene, s.time, fp);
    r.has_cost = true;
  }
  return r;
}

}  // namespace ms
