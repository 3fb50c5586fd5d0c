#include "bench/bench_report.h"

#include <cstdio>

#include <nlohmann/json.hpp>

namespace ms {
namespace {

using nlohmann::ordered_json;  // keeps the documented field order

ordered_json to_json(const Summary& s) {
  return {{"min", s.min}, {"median", s.median}, {"p95", s.p95}, {"max", s.max}, {"mean", s.mean}};
}

ordered_json to_json(const CountStats& c) { return {{"mean", c.mean}, {"p99", c.p99}, {"max", c.max}}; }

std::string format(const char* fmt, double a, double b, double c, double d) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
  return buf;
}

}  // namespace

std::string bench_json(const BenchSubject& subject, const BenchSettings& s, const BenchResult& r) {
  ordered_json j;
  j["schema"] = kBenchSchema;
  j["scene"] = {{"file", subject.scene_file}, {"name", subject.scene_name}};
  j["settings"] = {{"width", s.width},   {"height", s.height}, {"spp", s.spp},
                   {"frames", s.frames}, {"warmup", s.warmup}, {"time", s.time},
                   {"disable", subject.disable}, {"shader_cache", s.shader_cache},
                   {"specialize", subject.specialize}, {"passes", s.fused_post ? 1 : 2},
                   {"dispatch", dispatch_name(r.dispatch)},
                   {"compute_group", r.dispatch == Dispatch::compute ? ordered_json(group_name(r.group)) : ordered_json()},
                   {"overrides", subject.overrides}};
  j["machine"] = {{"backend", r.backend},
                  {"gl_renderer", r.gl_renderer},
                  {"gl_vendor", r.gl_vendor},
                  {"gl_version", r.gl_version}};
  j["startup_ms"] = {{"link", r.link_ms},
                     {"compile_link", r.compile_link_ms},
                     {"first_frame", r.first_frame_ms},
                     {"lazy_compile_forced_by", "1x1 frame"}};
  j["frame_ms"] = {{"gpu_timer", r.gpu_timer},
                   {"gpu", to_json(r.gpu_ms)},
                   {"wall", to_json(r.wall_ms)},
                   {"submit", to_json(r.submit_ms)}};
  j["uniform_lookups"] = {{"first_frames", r.lookups_first}, {"later_frames", r.lookups_later}};
  j["uniform_sets"] = {{"first_frames", r.sets_first}, {"per_timed_frame", r.sets_per_timed_frame}};
  ordered_json passes = ordered_json::array();
  for (const PassTiming& p : r.passes) passes.push_back({{"name", p.name}, {"wall", to_json(p.wall_ms)}});
  j["pass_ms"] = passes;
  if (!r.has_cost) {
    j["cost"] = nullptr;  // a Shadertoy shader has no step counters
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  }
  const BenchCost& c = r.cost;
  j["cost"] = {{"spp", 1},
               {"pixels", c.pixels},
               {"primary_steps", to_json(c.primary_steps)},
               {"shadow_steps", to_json(c.shadow_steps)},
               {"reflection_steps", to_json(c.reflection_steps)},
               {"sdf_evals", to_json(c.sdf_evals)},
               {"step_cap_fraction", c.step_cap_fraction},
               {"hit_fraction", c.hit_fraction},
               {"nonfinite_pixels", c.nonfinite_pixels}};
  if (r.primitive_evals) {  // a graph scene's (docs/scene-graph.md); absent for a map()
    j["cost"]["primitive_evals"] = to_json(*r.primitive_evals);
    j["graph"] = {{"eval", r.graph_eval},
                  {"prune_ms", r.prune_ms},
                  {"primitives_per_map_call", c.sdf_evals.mean > 0 ? r.primitive_evals->mean / c.sdf_evals.mean : 0.0}};
  }
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string bench_table(const BenchSubject& subject, const BenchSettings& s, const BenchResult& r) {
  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "scene     %s (%s)\nsettings  %dx%d, spp %d, %d frames after %d warm-up, %s shader, %s, %s dispatch\n",
                subject.scene_name.c_str(), subject.scene_file.c_str(), s.width, s.height, s.spp, s.frames,
                s.warmup, subject.specialize.c_str(), s.fused_post ? "one pass"
                : s.bloom                                          ? "main, bloom and post passes"
                                                                   : "main + post pass",
                dispatch_name(r.dispatch));
  out += buf;
  std::snprintf(buf, sizeof buf, "machine   %s, %s, GL %s\n", r.backend.c_str(), r.gl_renderer.c_str(),
                r.gl_version.c_str());
  out += buf;
  std::snprintf(buf, sizeof buf,
                "startup   link %.1f ms, compile+link %.1f ms (incl. a 1x1 frame), first frame %.1f ms (%s)\n",
                r.link_ms, r.compile_link_ms, r.first_frame_ms,
                s.shader_cache ? "shader cache allowed" : "cold: shader cache off");
  out += buf;
  out += "\nframe ms       min    median       p95       max\n";
  if (r.gpu_timer)
    out += format("  gpu   %9.2f %9.2f %9.2f %9.2f\n", r.gpu_ms.min, r.gpu_ms.median, r.gpu_ms.p95, r.gpu_ms.max);
  else
    out += "  gpu   (no GL_TIME_ELAPSED results from this driver)\n";
  out += format("  wall  %9.2f %9.2f %9.2f %9.2f\n", r.wall_ms.min, r.wall_ms.median, r.wall_ms.p95, r.wall_ms.max);
  out += format("  submit%9.3f %9.3f %9.3f %9.3f  (host, before the wait)\n", r.submit_ms.min, r.submit_ms.median,
                r.submit_ms.p95, r.submit_ms.max);
  std::snprintf(buf, sizeof buf, "  glGetUniformLocation calls: %lld in the first frames, %lld after\n", r.lookups_first,
                r.lookups_later);
  out += buf;
  std::snprintf(buf, sizeof buf, "  uniforms set: %lld in the first frames, %.1f a timed frame (unchanged ones are not sent)\n",
                r.sets_first, r.sets_per_timed_frame);
  out += buf;
  if (r.passes.size() > 1) {
    out += "\npass ms, each timed alone (wall)      min    median       p95       max\n";
    double sum = 0;
    for (const PassTiming& p : r.passes) {
      std::snprintf(buf, sizeof buf, "  %-28s %9.2f %9.2f %9.2f %9.2f\n", p.name.c_str(), p.wall_ms.min,
                    p.wall_ms.median, p.wall_ms.p95, p.wall_ms.max);
      out += buf;
      sum += p.wall_ms.median;
    }
    std::snprintf(buf, sizeof buf, "  sum of the medians %19.2f; the frame's median is %.2f (%.1f%% more)\n", sum,
                  r.wall_ms.median, sum > 0 ? 100.0 * (r.wall_ms.median / sum - 1.0) : 0.0);
    out += buf;
  }
  if (!r.has_cost) return out + "\ncost      none: a Shadertoy shader has no step counters\n";
  const BenchCost& c = r.cost;
  std::snprintf(buf, sizeof buf, "\ncost per pixel (spp 1, %lld pixels)  mean       p99       max\n", c.pixels);
  out += buf;
  auto row = [&](const char* name, const CountStats& st) {
    std::snprintf(buf, sizeof buf, "  %-18s %14.2f %9.0f %9.0f\n", name, st.mean, st.p99, st.max);
    out += buf;
  };
  row("primary steps", c.primary_steps);
  row("shadow steps", c.shadow_steps);
  row("reflection steps", c.reflection_steps);
  row("sdf evaluations", c.sdf_evals);
  if (r.primitive_evals) row("primitive evals", *r.primitive_evals);
  std::snprintf(buf, sizeof buf, "  step-cap pixels    %13.3f%%\n  hit pixels         %13.1f%%\n",
                100.0 * c.step_cap_fraction, 100.0 * c.hit_fraction);
  out += buf;
  std::snprintf(buf, sizeof buf, "  NaN/Inf pixels     %13lld\n", c.nonfinite_pixels);
  out += buf;
  if (r.primitive_evals) {
    std::snprintf(buf, sizeof buf, "\ngraph     %s; %.1f primitives a map() call\n", r.graph_eval.c_str(),
                  c.sdf_evals.mean > 0 ? r.primitive_evals->mean / c.sdf_evals.mean : 0.0);
    out += buf;
  }
  return out;
}

}  // namespace ms
