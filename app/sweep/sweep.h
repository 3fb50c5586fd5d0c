// `marchstudio sweep`: frame time against error for a grid of quality
// settings (sweep/sweep_grid.h), all in one process and one GL context so
// the times compare. Drives the same FrameRenderer as render and bench.
// What is measured, exactly: docs/speed-vs-error.md.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "bench/stats.h"
#include "sweep/sweep_grid.h"
#include "gl/context.h"
#include "scene/scene.h"
#include "shader/assemble.h"

namespace ms {

// Which frame time the fronts and the plot use.
enum class SweepClock {
  gpu,   // GL_TIME_ELAPSED around the frame (wall if the driver has no timer)
  wall,  // steady clock around draw + glFinish
  cpu,   // this process's CPU time over draw + glFinish: on llvmpipe the shader
         // threads' work, which other processes' load on a shared machine
         // barely changes (it can exceed the wall time: threads add up)
};
// "gpu" | "wall" | "cpu"; throws bad_input (key --time-by) otherwise.
SweepClock parse_sweep_clock(const std::string& name);
const char* sweep_clock_name(SweepClock c);

struct SweepSettings {
  int width = 640, height = 360;
  int spp = 1;        // samples of every row's image and of the same-spp reference
  int ref_spp = 16;   // samples of the supersampled reference
  int frames = 5;     // timed frames per row and round
  int rounds = 3;     // rounds over all rows; a row's time is its best round's median
  int warmup = 1;     // untimed frames before each row's frames in each round
  float time = 0.0f;  // scene time
  SweepGrid grid = SweepGrid::quick;
  SweepClock clock = SweepClock::gpu;
  // What draws every image and timed frame (--dispatch; automatic is
  // resolved by the caller first): the errors are the same with either.
  Dispatch dispatch = Dispatch::fragment;
  ComputeGroup group;
};

// Error of an image (and its AOVs) against a reference. NaN where a figure
// does not apply (no AOVs in the supersampled reference).
struct SweepError {
  double psnr = 0;           // dB over RGB of the final 8-bit-range image; +inf when identical
  double mae = 0;            // mean |difference| over RGB, in [0, 1]
  double depth_mean = 0;     // |t - t_ref| over pixels both hit, world units
  double depth_max = 0;
  double misclassified = 0;  // pixels hit in one and missed in the other, / all pixels
};

struct SweepRow {
  SweepConfig config;
  double compile_ms = 0;  // compile, link and a 1x1 frame (forces llvmpipe's lazy code generation)
  // The frame time: each round times `frames` frames of every row in turn;
  // a row's time is the smallest of its rounds' medians. A burst of load
  // from other processes on a shared machine then spoils one round, not
  // the row. gpu_ms and wall_ms summarise all its timed frames.
  double gpu_best_median = 0, wall_best_median = 0, cpu_best_median = 0;
  Summary gpu_ms, wall_ms, cpu_ms;
  BenchCost cost;         // from the AOV frame at `spp`: steps, cap fraction, map() calls
  SweepError same_spp;    // against the converged reference at the same spp
  SweepError supersampled;  // against the converged reference at ref_spp (psnr, mae only)
  // Against exact intersection (analytic scenes, spp 1): psnr and mae
  // against the row's own shading with its primary and reflection rays
  // intersected exactly (sdf_shaders/exact.glsl); depth and hit/miss of the
  // primary rays against the CPU's double-precision intersection.
  std::optional<SweepError> exact;
  bool pareto_same_spp = false, pareto_supersampled = false;  // on the time/PSNR front
};

struct SweepResult {
  std::string backend, gl_renderer, gl_vendor, gl_version;
  Dispatch dispatch = Dispatch::fragment;  // s.dispatch, as drawn
  bool gpu_timer = true;      // false: no GL_TIME_ELAPSED (gpu figures are 0; --time-by gpu uses wall)
  SweepClock clock = SweepClock::gpu;  // the time the fronts use
  Quality reference_quality;  // both references' settings
  std::string exact_status;   // "available", or why there is no exact reference
  std::vector<SweepRow> rows;
};

// The frame time a front is drawn against: the best round's median of
// r.clock (gpu falls back to wall where the driver has no timer).
double row_time_ms(const SweepResult& r, const SweepRow& row);

// Marks the rows on each time/PSNR Pareto front (no other row is at least
// as fast and at least as accurate, and better in one).
void mark_pareto(SweepResult& r);

// Measures every config on `scene` (already posed at s.time). `opts` carries
// the shader directory and include roots; its defines are added to every row.
// `progress` (may be empty) is told each row's index (from 1) and name
// before it is compiled, and each other phase with index 0.
SweepResult run_sweep(const Context& ctx, const Scene& scene, const std::vector<SweepConfig>& configs,
                      const AssembleOptions& opts, const SweepSettings& s,
                      const std::function<void(size_t, const std::string&)>& progress = {});

}  // namespace ms
