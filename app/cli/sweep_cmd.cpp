#include "cli/sweep_cmd.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "sweep/plot.h"
#include "sweep/sweep.h"
#include "sweep/sweep_report.h"
#include "cli/common_flags.h"
#include "cli/dispatch_flag.h"
#include "cli/flag_checks.h"
#include "cli/input_flags.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "pipeline/dispatch_probe.h"
#include "pipeline/frame_session.h"
#include "pipeline/input.h"
#include "pipeline/shader_dir.h"
#include "scene/animation.h"
#include "scene/quality.h"

namespace ms {
namespace fs = std::filesystem;

CLI::App* add_sweep_command(CLI::App& app, SweepArgs& a) {
  CLI::App* cmd =
      app.add_subcommand("sweep", "Frame time against error over a grid of quality settings (docs/speed-vs-error.md)");
  cmd->add_option("scene", a.input, "Scene .toml")->required();
  add_size_flag(cmd, "--size", a.size, "Image size WxH (default 640x360)");
  cmd->add_option("--frames", a.frames, "Timed frames per row in each round (default 5)");
  cmd->add_option("--rounds", a.rounds,
                  "Timing rounds over all rows; a row's time is its best round's median (default 3)");
  cmd->add_option("--warmup", a.warmup, "Untimed frames before each row's frames in each round (default 1)");
  cmd->add_option("--spp", a.spp, "Samples per pixel of every row and of the same-spp reference (default 1)");
  cmd->add_option("--ref-spp", a.ref_spp, "Samples per pixel of the supersampled reference (default 16)");
  cmd->add_option_function<std::string>(
         "--grid", [&a](const std::string& v) { a.grid = parse_sweep_grid(v); },
         "quick (about 30 rows) or full (adds a tracer factorial, about 80)")
      ->check(one_of({"quick", "full"}));
  cmd->add_option_function<std::string>(
         "--time-by",
         [&a](const std::string& v) {
           a.time_by = v == "auto" ? std::nullopt : std::optional<SweepClock>(parse_sweep_clock(v));
         },
         "The frame time the fronts and the plot use: gpu (GL timer), wall, cpu (this process's CPU time: "
         "steadier on a shared machine), or auto (default: cpu on a software GL such as llvmpipe, else gpu)")
      ->check(one_of({"auto", "gpu", "wall", "cpu"}));
  cmd->add_option("--only", a.only, "Measure only these rows of the grid, by name (e.g. textbook,balanced)")
      ->delimiter(',');
  cmd->add_option("-o,--out", a.out, "Directory for <scene>.sweep.csv, .json and .png (default .)");
  add_backend_flag(cmd, a.backend);
  cmd->add_flag("-q,--quiet", a.quiet, "No progress lines on stderr");
  LoadFlagChoice load;
  load.defines = load.disable = load.shadertoy = false;
  load.preset_help = "The preset the rows vary around (default balanced)";
  load.no_specialize_help =
      "Measure the generic shader: every feature compiled, values as uniforms (docs/specialization.md)";
  add_load_flags(cmd, a.load, load);
  add_dispatch_flag(cmd, a.dispatch,
                    "Draw every row as a fragment pass (default), a compute dispatch, or auto (docs/gpu.md)");
  add_compute_group_flag(cmd, a.compute_group);
  return cmd;
}

namespace {

void check_range(int v, int lo, int hi, const char* flag) {
  if (v < lo || v > hi)
    fail_input(std::string(flag) + " must be in " + std::to_string(lo) + ".." + std::to_string(hi), {}, 0, flag);
}

std::string size_text(ImageSize s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

std::string command_line(const SweepArgs& a) {
  std::string c = "marchstudio sweep " + a.input + " --size " + size_text(a.size) + " --frames " + std::to_string(a.frames) +
                  " --rounds " + std::to_string(a.rounds) + " --warmup " + std::to_string(a.warmup) + " --spp " + std::to_string(a.spp) + " --ref-spp " +
                  std::to_string(a.ref_spp) + " --grid " + sweep_grid_name(a.grid);
  const LoadFlags& l = a.load;
  if (l.preset != "balanced") c += " --preset " + l.preset;
  if (a.time_by) c += std::string(" --time-by ") + sweep_clock_name(*a.time_by);
  if (!a.only.empty()) {
    c += " --only ";
    for (size_t i = 0; i < a.only.size(); ++i) c += (i ? "," : "") + a.only[i];
  }
  if (a.backend != Backend::automatic) c += std::string(" --backend ") + backend_name(a.backend);
  if (l.no_specialize) c += " --no-specialize";
  if (l.graph_eval != GraphEval::auto_)
    c += std::string(" --graph-eval ") + (l.graph_eval == GraphEval::inline_ ? "inline" : "interpreter");
  if (l.no_prune) c += " --no-prune";
  if (a.dispatch != Dispatch::fragment) c += std::string(" --dispatch ") + dispatch_name(a.dispatch);
  for (const std::string& o : l.overrides.as_given) {  // "--set KEY=VALUE": the value quoted, brackets are shell globs
    const size_t space = o.find(' ');
    std::string value = o.substr(space + 1);
    for (size_t at = 0; (at = value.find('\'', at)) != std::string::npos; at += 4) value.replace(at, 1, "'\\''");
    c += " " + o.substr(0, space) + " '" + value + "'";
  }
  return c;
}

// The measuring settings from the flags, each checked.
SweepSettings sweep_settings(const SweepArgs& a) {
  SweepSettings s;
  s.width = a.size.width;
  s.height = a.size.height;
  check_range(a.frames, 1, 10000, "--frames");
  check_range(a.warmup, 0, 10000, "--warmup");
  check_range(a.rounds, 1, 100, "--rounds");
  check_range(a.spp, 1, 1024, "--spp");
  check_range(a.ref_spp, 1, 1024, "--ref-spp");
  s.frames = a.frames;
  s.warmup = a.warmup;
  s.rounds = a.rounds;
  s.spp = a.spp;
  s.ref_spp = a.ref_spp;
  s.grid = a.grid;
  if (a.time_by) s.clock = *a.time_by;
  s.dispatch = a.dispatch;
  s.group = a.compute_group.value_or(ComputeGroup{});
  return s;
}

// The grid's rows, a graph's cell-size rows added, cut to --only's.
std::vector<SweepConfig> sweep_rows(const SweepArgs& a, const LoadedInput& in, const AssembleOptions& opts) {
  std::vector<SweepConfig> configs = sweep_grid(in.scene.quality, a.grid, a.load.preset);
  if (opts.graph) {  // the pruning grid's cells: half and twice the planned size
    const GraphEvalPlan& plan = opts.graph->plan;
    const glm::vec3 cell = plan.pruned() ? plan.levels[0].cell : glm::vec3(0.0f);
    for (SweepConfig& c : cell_size_rows(in.scene.quality, std::max({cell.x, cell.y, cell.z}), a.load.preset))
      configs.push_back(std::move(c));
  }
  if (a.only.empty()) return configs;
  std::vector<SweepConfig> kept;
  for (const std::string& name : a.only) {
    const auto it = std::find_if(configs.begin(), configs.end(), [&](const SweepConfig& c) { return c.name == name; });
    if (it == configs.end())
      fail_input("no row '" + name + "' in the " + sweep_grid_name(a.grid) + " grid", {}, 0, "--only",
                 "row names are in the first column of the CSV, e.g. textbook, balanced, omega=1.5");
    kept.push_back(*it);
  }
  return kept;
}

// --dispatch auto: probed on the scene's own pass (pipeline/dispatch_probe.h).
void choose_dispatch(FrameSession& session, const LoadedInput& in, const Scene& posed, const AssembleOptions& opts,
                     const SweepArgs& a, SweepSettings& s) {
  PreparedFrame probe;
  probe.in = in;
  probe.in.scene.bloom.enabled = false;  // the rows draw without bloom
  probe.opts = opts;
  probe.opts.graph = nullptr;  // as before: the probe times the pass without building a pruned grid
  probe.post_src = assemble_post(in.scene.render.tonemap, true, opts);
  StillFrame f;
  f.in.scene = &posed;
  f.in.time = s.time;
  f.params.exposure = posed.render.exposure;
  const DispatchChoice c = session.load(probe).choose(s.dispatch, a.compute_group, f, !a.quiet);
  s.dispatch = c.dispatch;
  s.group = c.group;
}

}  // namespace

int run_sweep_command(const SweepArgs& a) {
  // The shader render and bench build: specialized to the scene (and each row's quality).
  AssembleOptions opts = load_assemble_options(a.load);
  SweepSettings s = sweep_settings(a);
  LoadedInput loaded = load_input_scene(a.input, {}, opts, {}, a.load.overrides.set);
  prepare_graph_shape(loaded.scene, opts);  // once: the rows of its cell size take it from here
  assemble_input(loaded, opts);
  const LoadedInput& in = loaded;
  if (in.shadertoy)
    fail_input("sweep needs an SDF scene: a Shadertoy shader has no quality settings", a.input, 0, {},
               "wrap the map in a scene .toml");
  s.time = in.scene.render.time;
  check_compute_input(s.dispatch, in);
  const std::vector<SweepConfig> configs = sweep_rows(a, in, opts);
  // Outputs are checked before any work: the directory is made if missing.
  const fs::path dir(a.out);
  std::error_code ec;
  if (!fs::is_directory(dir, ec) && !fs::create_directory(dir, ec))
    fail_input("cannot create the output directory", a.out, 0, "--out", ec ? ec.message() : "");
  const std::string stem = in.scene.name.empty() ? fs::path(a.input).stem().string() : in.scene.name;
  const fs::path csv = dir / (stem + ".sweep.csv"), json = dir / (stem + ".sweep.json"),
                 png = dir / (stem + ".sweep.png");
  check_output_path(png);

  // Cold, repeatable compile times, as bench (the driver reads these at context creation).
  ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  ::setenv("__GL_SHADER_DISK_CACHE", "0", 1);
  FrameSession session;
  const Context& ctx = session.context(a.backend);
  if (!a.time_by) s.clock = ctx.info().software() ? SweepClock::cpu : SweepClock::gpu;
  const Scene posed = animated(in.scene, s.time);
  if (s.dispatch == Dispatch::automatic) choose_dispatch(session, in, posed, opts, a, s);
  const size_t n = configs.size();
  const SweepResult r = run_sweep(ctx, posed, configs, opts, s, [&](size_t i, const std::string& name) {
    if (a.quiet) return;
    if (i == 0) std::fprintf(stderr, "sweep: %s\n", name.c_str());
    else std::fprintf(stderr, "sweep: [%zu/%zu] %s\n", i, n, name.c_str());
  });

  const SweepSubject subject{a.input, in.scene.name, command_line(a), specialization_name(opts.specialize)};
  write_file_atomic(csv, sweep_csv(r));
  write_file_atomic(json, sweep_json(subject, s, r));
  const SweepPlot plot = plot_sweep(r, in.scene.name + ", " + size_text(a.size) + ", " + r.gl_renderer);
  write_image(plot.image, png);
  if (!plot.has_text && !a.quiet)
    std::fprintf(stderr, "sweep: no usable font for the plot's labels; drawn without text\n");
  std::fputs(sweep_table(subject, s, r).c_str(), stdout);
  std::printf("\nwrote %s, %s, %s\n", csv.string().c_str(), json.string().c_str(), png.string().c_str());
  return 0;
}

}  // namespace ms
