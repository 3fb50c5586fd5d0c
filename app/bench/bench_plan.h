// One bench of a scene, from its job to its result, as `marchstudio bench`
// and the Python package's Scene.bench() both take it: the frame prepared
// as render draws it to a PNG, the counting pass assembled beside it, the
// settings filled from the scene where the caller left them at 0.
//
//   BenchPlan b = plan_bench(job, {640, 360}, 30, 3);   // throws ms::Error
//   b.s.dispatch = ...;                                   // the caller's extras
//   check_bench_settings(b.s);                            // before the context
//   session.context(job.backend);
//   BenchResult r = run_planned_bench(session, b);
#pragma once
#include <optional>

#include <glm/vec2.hpp>

#include "bench/bench.h"
#include "pipeline/frame_job.h"
#include "pipeline/prepare.h"

namespace ms {

struct BenchPlan {
  PreparedFrame p;
  AssembleOptions count_opts;               // the counting pass's options (AOV counters compiled in)
  std::optional<ShaderSource> counting;     // none for a Shadertoy shader: its passes are timed only
  BenchSettings s;
  Scene posed;                              // keyframed values at s.time, as render poses them
};

// `size` 0: the scene's; the job's spp < 0 is kept for check_bench_settings
// to refuse with its flag's name.
BenchPlan plan_bench(const FrameJob& job, glm::ivec2 size, int frames, int warmup);

// The timed frames, then a graph scene's primitive count (bench/bench.h).
BenchResult run_planned_bench(FrameSession& session, const BenchPlan& b);

}  // namespace ms
