#include "cli/mesh_cmd.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli/common_flags.h"
#include "cli/flag_checks.h"
#include "cli/frame_flags.h"
#include "cli/input_flags.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/format.h"
#include "pipeline/mesh_job.h"
#include "pipeline/mesh_sequence.h"
#include "pipeline/progress.h"
#include "pipeline/shader_dir.h"
#include "pipeline/still_job.h"

namespace ms {

namespace fs = std::filesystem;

CLI::App* add_mesh_command(CLI::App& app, MeshArgs& a) {
  CLI::App* cmd = app.add_subcommand("mesh", "Export a scene's surface as a mesh or an OpenVDB level set (docs/mesh.md)");
  cmd->add_option("scene", a.input, "Scene .toml with a map() or a graph, or a graph file (.json) alone")->required();
  cmd->add_option("-o,--output", a.output,
                  "Output: .obj (with .mtl), .ply, .stl, .glb, or .vdb (a level set) (default: <scene>.obj)")
      ->check(not_empty());
  cmd->add_option("--resolution", a.resolution, "Cells along the longest side of the box (default 256, at most 4096)")
      ->check(CLI::Range(8, kMaxMeshCells));
  cmd->add_option("--voxel", a.voxel,
                  "The cell's size in world units, instead of --resolution (at least the box's longest side / 4096)")
      ->check(positive());
  cmd->add_option("--bounds", a.bounds, "The box to mesh, x0,y0,z0,x1,y1,z1 (default: the scene's [bounds])")
      ->delimiter(',')
      ->expected(6);
  cmd->add_flag("--planes", a.planes, "Include the scene's [[planes]], cut by the box (default: left out)");
  cmd->add_option("--band", a.band, "A .vdb level set's half-width in voxels (default 3)")->check(CLI::Range(1, 64));
  cmd->add_option_function<double>(
         "--time", [&a](double v) { a.time = v; }, "Scene time in seconds, finite (default: the scene's)")
      ->check(seconds_value());
  cmd->add_option_function<std::string>(
         "--frames", [&a](const std::string& v) { a.frames = parse_frame_range(v); },
         "Mesh frames A..B (both included), one file each, to -o PATTERN, e.g. out/f_%04d.obj")
      ->check(not_empty());
  cmd->add_option_function<double>(
      "--fps", [&a](double v) { a.fps = v; }, "Frames per second: frame f of --frames is at time f / fps (default 24)");
  cmd->add_flag("--force", a.force,
                "With --frames: mesh every frame again, even those on disk with this run's fingerprint");
  cmd->add_flag("--strict", a.strict,
                "Fail (exit 1, nothing written) when any sample of map() is NaN or Inf; without it a warning");
  cmd->add_flag("--json", a.json, "Print the report as one JSON object (schema marchstudio.mesh/1)");
  cmd->add_flag("-v,--verbose", a.verbose, "Print the grid, accuracy, check and stage times");
  cmd->add_option("--timeout", a.timeout, "Give up after this many seconds (0: no limit): exit 3, nothing written")
      ->check(seconds_value())
      ->check(non_negative());
  add_backend_flag(cmd, a.backend);
  LoadFlagChoice load;
  load.disable = false;
  load.shadertoy = false;
  load.no_specialize_help = "Sample with the generic shader (docs/specialization.md)";
  add_load_flags(cmd, a.load, load);
  return cmd;
}

MeshJob make_mesh_job(const MeshArgs& a) {
  MeshJob job;
  set_load_fields(job.frame, a.load);
  job.frame.input = a.input;
  job.frame.backend = a.backend;
  job.frame.verbose = a.verbose;
  // A --jobs line's values arrive without the flags' checks.
  if (!std::isfinite(a.timeout) || a.timeout < 0)
    fail_input("--timeout must be a number of seconds >= 0 (0: no limit)", {}, 0, "--timeout");
  job.frame.timeout = a.timeout;
  job.frame.strict = a.strict;
  if (a.time && (!std::isfinite(*a.time) || std::abs(*a.time) > FLT_MAX))
    fail_input("--time must be a finite number of seconds", {}, 0, "--time");
  if (a.time) job.frame.time = static_cast<float>(*a.time);
  if (!std::isfinite(a.voxel) || a.voxel < 0) fail_input("--voxel must be a number > 0", {}, 0, "--voxel");
  job.output = a.output.empty() ? fs::path(fs::path(a.input).stem().string() + ".obj") : fs::path(a.output);
  job.resolution = a.resolution;
  job.voxel = a.voxel;
  if (!a.bounds.empty()) {
    const MeshBox b{{a.bounds[0], a.bounds[1], a.bounds[2]}, {a.bounds[3], a.bounds[4], a.bounds[5]}};
    if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z))
      fail_input("--bounds must be x0,y0,z0,x1,y1,z1 with each minimum below its maximum", {}, 0, "--bounds");
    job.bounds = b;
  }
  job.planes = a.planes;
  job.band = a.band;
  return job;
}

namespace {

// On a terminal, one line redrawn in place: the stage, a percentage and an
// ETA from the fraction done; elsewhere nothing (the summary line says it).
MeshProgress progress_for(bool tty) {
  if (!tty) return {};
  const Clock::time_point start = Clock::now();
  return [start](const char* stage, double fraction) {
    const double t = seconds_since(start);
    const double eta = fraction > 0.02 ? t * (1.0 - fraction) / fraction : -1.0;
    std::fprintf(stderr, "\r\033[Kmesh: %-9s %3d%%  %s elapsed, ETA %s", stage, static_cast<int>(fraction * 100.0),
                 format_duration(t).c_str(), eta < 0 ? "-" : format_duration(eta).c_str());
    std::fflush(stderr);
  };
}

// `--frames`: the flags checked before any file is read, then the frames.
int run_mesh_sequence(const MeshArgs& a) {
  if (a.time)
    fail_input("--time conflicts with --frames: each frame's time is frame / fps", {}, 0, "--time",
               "shift the animation with --frames instead");
  if (a.json) fail_input("--json reports one mesh, and --frames makes several", {}, 0, "--json");
  const double fps = a.fps.value_or(kSceneFps);
  if (!std::isfinite(fps) || fps <= 0)
    fail_input("--fps must be a positive number, got " + format_number(fps), {}, 0, "--fps");
  // Frame f is at time f / fps, a 32-bit float in the shader.
  const double last_time = std::max(std::abs(double(a.frames->first)), std::abs(double(a.frames->last))) / fps;
  if (!(last_time <= FLT_MAX))
    fail_input("--fps " + format_number(fps) + " puts frame " + std::to_string(a.frames->last) + " at time " +
                   format_number(last_time) + " s, beyond a 32-bit float",
               {}, 0, "--fps", "give frames per second, e.g. --fps 24");
  MeshSequenceJob job;
  job.range = *a.frames;
  job.fps = fps;
  job.force = a.force;
  std::string pattern = a.output;
  if (pattern.empty()) {
    // <stem>_%04d.obj, with any '%' of the stem escaped for the pattern.
    for (char c : fs::path(a.input).stem().string()) pattern += c == '%' ? std::string("%%") : std::string(1, c);
    pattern += "_%04d.obj";
  }
  job.pattern = FramePattern(pattern);
  job.mesh = make_mesh_job(a);  // its output and time are each frame's (mesh_sequence())
  FrameSession session;
  mesh_sequence(job, session, isatty(STDERR_FILENO) == 1);
  return 0;
}

}  // namespace

int run_mesh(const MeshArgs& a) {
  if (a.frames) return run_mesh_sequence(a);
  if (a.fps || a.force)
    fail_input(std::string(a.force ? "--force" : "--fps") + " needs --frames", {}, 0, a.force ? "--force" : "--fps",
               "e.g. --frames 0..23 -o out/f_%04d.obj");
  if (has_frame_field(a.output))
    fail_input("-o '" + a.output + "' has a frame field but there is no --frames", {}, 0, "-o",
               "add --frames A..B, or name one file");
  const MeshJob job = make_mesh_job(a);
  const bool tty = isatty(STDERR_FILENO) && !a.json;
  FrameSession session;
  say_removed_temps(mesh_files(job.output));
  const MeshReport r = mesh_scene(job, session, progress_for(tty));
  if (tty) std::fputs("\r\033[K", stderr);
  if (a.json) {
    std::printf("%s\n", mesh_report_json(r).c_str());
  } else {
    for (const std::string& path : r.written) std::printf("%s\n", path.c_str());  // as render prints its image's
    std::fprintf(stderr, "marchstudio: wrote %s\n", mesh_summary(r).c_str());
    if (a.verbose)
      for (const std::string& line : mesh_report_lines(r)) std::fprintf(stderr, "  %s\n", line.c_str());
  }
  if (!r.check.ok() && r.format != MeshFormat::vdb)
    std::fprintf(stderr, "marchstudio: warning: %s: the mesh check found %s\n", r.output.c_str(),
                 r.check.summary().c_str());
  return 0;
}

}  // namespace ms
