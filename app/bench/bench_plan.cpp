#include "bench/bench_plan.h"

#include "render/aov.h"
#include "scene/animation.h"
#include "shader/assemble.h"

namespace ms {

BenchPlan plan_bench(const FrameJob& job, glm::ivec2 size, int frames, int warmup) {
  BenchPlan b;
  // Timed frames as render draws them to a PNG: one pass at spp 1, bloom
  // as the scene says (docs/post.md).
  b.p = prepare(job, true);
  const LoadedInput& in = b.p.in;
  b.count_opts = job.assemble_options();
  b.count_opts.defines = aov_defines();
  b.count_opts.graph = b.p.opts.graph;  // the shape prepare() made
  if (!in.shadertoy) b.counting = assemble_scene(in.scene, b.count_opts);
  BenchSettings& s = b.s;
  s.width = size.x > 0 ? size.x : in.scene.render.width;
  s.height = size.x > 0 ? size.y : in.scene.render.height;
  s.spp = job.spp < 0 ? job.spp : b.p.fp.spp;  // run_bench rejects a negative one with the flag's name
  s.frames = frames;
  s.warmup = warmup;
  s.time = in.scene.render.time;
  s.fused_post = b.p.fp.fused_post;
  s.bloom = in.scene.bloom.enabled;
  b.posed = animated(in.scene, s.time);
  return b;
}

BenchResult run_planned_bench(FrameSession& session, const BenchPlan& b) {
  BenchResult r = run_bench(session, b.p, b.posed, b.counting ? &*b.counting : nullptr, b.s);
  if (b.p.in.scene.graph) count_graph_cost(session.job(), b.p, b.posed, b.s, b.count_opts, r);
  return r;
}

}  // namespace ms
