#include "cli/bench_cmd.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <cstdlib>
#include <regex>

#include "bench/bench.h"
#include "bench/bench_plan.h"
#include "bench/bench_report.h"
#include "cli/common_flags.h"
#include "cli/dispatch_flag.h"
#include "cli/flag_checks.h"
#include "cli/input_flags.h"
#include "core/error.h"
#include "pipeline/bloom_setup.h"
#include "pipeline/dispatch_probe.h"
#include "pipeline/input.h"
#include "pipeline/nonfinite.h"
#include "pipeline/shader_dir.h"
#include "render/bounds_check.h"
#include "render/uniforms.h"
#include "shader/assemble.h"

namespace ms {

CLI::App* add_bench_command(CLI::App& app, BenchArgs& a) {
  CLI::App* cmd = app.add_subcommand("bench", "Time a scene and count its steps per pixel (docs/bench.md)");
  cmd->add_option("scene", a.input, "Scene .toml, a graph file (.json) or a Shadertoy shader (.glsl, .json): its passes are timed")->required();
  add_size_flag(cmd, "--size", a.size, "Image size WxH (default: the scene's)")->check(not_empty());
  cmd->add_option("--frames", a.frames, "Timed frames (default 30)");
  cmd->add_option("--warmup", a.warmup, "Untimed frames before them (default 3)");
  cmd->add_option("--spp", a.spp, "Samples per timed frame, 1..1024 (default: the scene's; the cost pass uses 1)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--json", a.json, "Print one JSON object (schema marchstudio.bench/1) instead of a table");
  cmd->add_flag("--shader-cache", a.shader_cache,
                "Allow the driver's on-disk shader cache and the pruned-grid cache (default: off, so compile and "
                "pruning times are cold)");
  add_backend_flag(cmd, a.backend);
  cmd->add_flag("--strict", a.strict,
                "Fail (exit 1) when any pixel of the counting pass has a NaN or Inf (colour or AOV); "
                "the report is still printed");
  LoadFlagChoice load;
  load.defines = false;
  load.no_specialize_help =
      "Time the generic shader: every feature compiled, values as uniforms (docs/specialization.md)";
  add_load_flags(cmd, a.load, load);
  add_dispatch_flag(cmd, a.dispatch,
                    "Draw the scene pass as a fragment pass (default), a compute dispatch, or auto (docs/gpu.md)");
  add_compute_group_flag(cmd, a.compute_group);
  cmd->add_flag("-v,--verbose", a.verbose, "Say which dispatch --dispatch auto chose, and why");
  return cmd;
}

namespace {

// Mesa (llvmpipe included) and NVIDIA keep compiled shaders on disk; a
// cache hit turns a 100 ms compile into 10 ms, so a second bench run would
// report a different compile time. Read by the driver at context creation.
void set_shader_cache(bool allowed) {
  ::setenv("MESA_SHADER_CACHE_DISABLE", allowed ? "false" : "true", 1);
  ::setenv("__GL_SHADER_DISK_CACHE", allowed ? "1" : "0", 1);
}

}  // namespace

int run_bench_command(const BenchArgs& a) {
  FrameJob job;
  job.label = a.input;
  job.input = a.input;
  job.spp = a.spp;
  job.backend = a.backend;
  set_load_fields(job, a.load);
  BenchPlan plan = plan_bench(job, {a.size.width, a.size.height}, a.frames, a.warmup);  // bench/bench_plan.h
  PreparedFrame& p = plan.p;
  p.keep_pruned = a.shader_cache;  // cold, like the driver's cache: the pruning pass is timed
  const LoadedInput& in = p.in;
  BenchSettings& s = plan.s;
  report_input_warnings(in.warnings, a.input, a.strict);

  s.shader_cache = a.shader_cache;
  s.dispatch = a.dispatch;
  s.group = a.compute_group;
  s.verbose = a.verbose;
  check_compute_input(s.dispatch, in);
  check_bench_settings(s);  // before the (slow) context
  set_shader_cache(s.shader_cache);
  FrameSession session;
  session.context(job.backend);
  const BenchResult r = run_planned_bench(session, plan);
  const Scene& posed = plan.posed;
  if (!in.shadertoy) {
    const std::string bw = bounds_warning(a.input, check_bounds(posed, p.opts, [&](const Program& prog) {  // render/bounds_check.h
      set_scene_uniforms(prog, posed, s.width, s.height, s.time, 0);
    }));
    if (!bw.empty()) std::fprintf(stderr, "marchstudio: %s\n", bw.c_str());
  }
  const BenchSubject subject{a.input, in.scene.name, a.load.disable, specialization_name(p.opts.specialize),
                             a.load.overrides.as_given};
  const std::string text = a.json ? bench_json(subject, s, r) : bench_table(subject, s, r);
  std::fputs(text.c_str(), stdout);
  guard_nonfinite({a.input, a.strict, {}, {}}, r.cost.nonfinite_pixels, r.cost.pixels);  // pipeline/nonfinite.h
  return 0;
}

}  // namespace ms
