// `marchstudio bench`: how long a scene takes to compile and to render, and
// what it costs in deterministic units (steps and map() calls per pixel).
// Draws through the frame pipeline's session, as `render` does (pipeline/frame_session.h).
// Output format and schema: docs/bench.md.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "bench/stats.h"
#include "gl/context.h"
#include "io/image.h"
#include "pipeline/frame_session.h"
#include "render/frame.h"
#include "render/graph.h"
#include "render/scene_drawer.h"
#include "scene/scene.h"
#include "preprocess/preprocess.h"

namespace ms {

struct BenchSettings {
  int width = 0, height = 0;
  int spp = 1;        // samples per timed frame (the counting pass always uses 1)
  int frames = 30;    // timed frames
  int warmup = 3;     // untimed frames drawn first
  float time = 0.0f;  // scene time of every frame (uFrame is 0: every frame does the same work)
  // Whether the drivers' on-disk shader caches may serve the compile. Off by
  // default, so compile times are cold and repeatable (the caller sets the
  // driver environment before creating the context: see bench_cmd.cpp).
  bool shader_cache = false;
  // The main program writes the image itself (FrameParams::fused_post):
  // assembled with fused_post_defines(), for spp 1. Reported as passes 1.
  bool fused_post = false;
  // The timed frames run the scene's [post.bloom] stage (the session's,
  // pipeline/frame_session.h), with a post pass assembled with bloom.
  bool bloom = false;
  // Which pass draws the scene (--dispatch): fragment or compute, or
  // automatic, measured once the programs exist (pipeline/dispatch_probe.h);
  // the group given, if any. Buffer passes stay fragment.
  Dispatch dispatch = Dispatch::fragment;
  std::optional<ComputeGroup> group;
  bool verbose = false;  // -v: what auto chose, and why
};

// The deterministic cost of one frame at spp 1, from the AOV counters.
// Every figure is over ALL pixels (sky pixels included: their primary rays
// cost steps too); fractions are counts / pixels.
struct BenchCost {
  long long pixels = 0;
  CountStats primary_steps;     // map() calls of the primary ray
  CountStats shadow_steps;      // all shadow rays of the pixel (every light, every bounce)
  CountStats reflection_steps;  // all reflection segments of the pixel
  CountStats sdf_evals;         // every map() call: trace, normals, shadows, AO, reflections
  double step_cap_fraction = 0; // primary ray ran out of MAX_STEPS (neither converged nor escaped)
  double hit_fraction = 0;      // primary ray hit a surface
  long long nonfinite_pixels = 0;  // pixels with NaN/Inf in any channel of the counting pass (colour or AOV)
  std::optional<CountStats> primitive_evals;  // a graph scene's, when counted (its own pass)
};

// Cost from the AOVs read back from a spp-1 AOV frame (channels
// steps, shadow_steps, reflection_steps, sdf_evals, step_cap, hit).
BenchCost measure_cost(const Image& aovs);

// The counting pass: one frame of `counting` (the scene assembled with
// AOV_OUTPUTS 1), compiled for the job's dispatch and drawn with its post
// pass and bloom, at one sample per pixel centre, so the counts are those
// of the image's primary rays and nothing random; `fp` gives the size and
// exposure (spp, AOVs and fusing are set here). bench and test both count
// with it.
BenchCost count_frame_cost(FramePrograms& job, const ShaderSource& counting, const Scene& posed, float time,
                           FrameParams fp);

// One pass of the graph, timed on its own (glFinish before and after).
struct PassTiming {
  std::string name;
  Summary wall_ms;
};

struct BenchResult {
  std::string backend, gl_renderer, gl_vendor, gl_version;
  Dispatch dispatch = Dispatch::fragment;  // what drew the scene pass (auto resolved)
  ComputeGroup group;                      // its work group, when compute
  // Startup, milliseconds of wall time. llvmpipe compiles a program's
  // machine code lazily at its first draw, so link_ms (the Program
  // constructors returning) hides most of the work: compile_link_ms also
  // includes a 1x1 frame drawn and finished, which forces it.
  double link_ms = 0, compile_link_ms = 0;
  // From before compiling to the end of the first full-size frame (finished).
  double first_frame_ms = 0;
  bool gpu_timer = true;  // false: the driver reported no GL_TIME_ELAPSED results (all 0)
  Summary gpu_ms;         // GL_TIME_ELAPSED around each frame's draw (samples + post)
  Summary wall_ms;        // steady clock around draw + glFinish
  // Host time to issue a frame's GL commands (the draw call returning,
  // before glFinish): the per-frame host work a fast GPU waits on.
  Summary submit_ms;
  // Program::gl_lookups() made by the startup frames (1x1 and first
  // full-size) and by every later one (warm-up, timed, pass by pass): the
  // later count is 0 when uniform locations are kept.
  long long lookups_first = 0, lookups_later = 0;
  // Program::gl_uniform_sets() made by the startup frames, and by the timed
  // frames' draws over their count: a program keeps its uniforms, so a still
  // scene at spp 1 sets none a frame (render/program.h).
  long long sets_first = 0;
  double sets_per_timed_frame = 0;
  // Each pass's wall time in frames timed pass by pass (a multi-pass
  // Shadertoy shader: its buffers, then the Image pass with the post pass);
  // a graph of one pass: the frame's wall time, no second frame drawn.
  std::vector<PassTiming> passes;
  bool has_cost = false;  // an SDF scene: its counting pass ran
  // A graph scene: primitives evaluated per pixel over every map() call
  // (a second counting pass), the pruning pass's time and its grid.
  std::optional<CountStats> primitive_evals;
  double prune_ms = 0.0;
  std::string graph_eval;  // "inline", "interpreter" or "interpreter, pruned: grid ..."
  BenchCost cost;
};

// Throws bad_input for settings out of range (keys --frames, --warmup,
// --spp); run_bench() calls it too, callers may call it before making a
// context.
void check_bench_settings(const BenchSettings& s);

// Times the graph of `p` (a scene's one pass, or a Shadertoy shader's
// buffers and Image pass: frames follow on from one another, as a
// sequence's) drawn by `session` (its context made), `posed` at s.time,
// then each pass on its own, and, given `counting` (the scene assembled
// with AOV_OUTPUTS 1), counts its steps.
// A graph scene's figures (BenchResult::primitive_evals, prune_ms,
// graph_eval): a second counting pass that counts primitives, with
// `count_opts` (the counting pass's options).
void count_graph_cost(FramePrograms& job, const PreparedFrame& p, const Scene& posed, const BenchSettings& s,
                      AssembleOptions count_opts, BenchResult& r);

BenchResult run_bench(FrameSession& session, const PreparedFrame& p, const Scene& posed, const ShaderSource* counting,
                      const BenchSettings& s);

}  // namespace ms
