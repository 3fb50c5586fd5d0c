#include "cli/view_cmd.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <regex>
#include <sstream>

#include "cli/common_flags.h"
#include "cli/dispatch_flag.h"
#include "cli/flag_checks.h"
#include "cli/frame_flags.h"
#include "cli/glslviewer_flags.h"
#include "cli/input_flags.h"
#include "core/error.h"
#include "core/format.h"
#include "gl/context.h"
#include "io/input_file.h"
#include "io/video.h"
#include "live/viewer.h"
#include "mesh/mesh.h"
#include "pipeline/dispatch_probe.h"
#include "pipeline/input.h"
#include "pipeline/shader_dir.h"
#include "scene/animation.h"
#include "scene/load.h"
#include "scene/quality.h"
#include "shader/scene_params.h"

namespace ms {
namespace fs = std::filesystem;

CLI::App* add_view_command(CLI::App& app, ViewArgs& a) {
  CLI::App* cmd = app.add_subcommand("view", "Open a window on a scene (.toml) or Shadertoy shader (.glsl); "
                                             "reloads on every save (docs/viewer.md)");
  cmd->add_option("input", a.input, "Scene .toml, graph file (.json) or Shadertoy .glsl/.frag/.json")->required();
  add_size_flag(cmd, "--size", a.size, "Window size WxH (default: the scene's, at most 1280x720)")->check(not_empty());
  cmd->add_option("--debug-view", a.debug_view,
                  "Start in a debug view: 0 lit, 1 steps, 2 normals, 3 depth, 4 AO, 5 shadow, 6 material id")
      ->check(CLI::Range(0, 6));
  cmd->add_option_function<double>(
         "--time", [&a](double v) { a.time = v; },
         "Start time in seconds, any finite value as for render (default: the scene's [render] time)")
      ->check(seconds_value());
  cmd->add_option_function<std::string>(
         "--accumulate",
         [&a](const std::string& v) {
           if (v == "unlimited") return void(a.accumulate = 0);
           char* end = nullptr;
           const long n = std::strtol(v.c_str(), &end, 10);
           if (v.empty() || *end != '\0' || n < 1 || n > 1 << 20)
             fail_input("invalid --accumulate '" + v + "'", {}, 0, "--accumulate",
                        "a number of samples 1..1048576 (1: off), or unlimited");
           a.accumulate = static_cast<int>(n);
         },
         "While nothing changes, add jittered samples up to N (render --spp N's), or without limit (unlimited); "
         "1: off (default: the scene's [render] spp)");
  cmd->add_option("--record-dir", a.record_dir,
                  "Where F9's recording writes frame_%04d.png (default: <input stem>_frames)")
      ->check(not_empty());
  cmd->add_option("--record-fps", a.record_fps, "Frames per second of a recording (default 24; a Shadertoy shader's 60)")
      ->check(CLI::Range(0.001, 1000.0));
  cmd->add_option_function<std::string>(
         "--record",
         [&a](const std::string& v) {
           try {
             a.record_frames = parse_frame_range(v);
           } catch (const Error&) {  // its message names --frames
             fail_input("invalid --record '" + v + "'", {}, 0, "--record", "frames A..B, as render --frames");
           }
         },
         "Record frames A..B at start, as render --frames A..B would (scripts)")
      ->check(not_empty());
  cmd->add_option("--record-video", a.record_video, "Encode each recording into this file with ffmpeg (e.g. out.mp4)")
      ->check(not_empty());
  cmd->add_option("--audio-device", a.audio_device,
                  "ALSA device that plays a Shadertoy music input in step with time (default: default; none: silent)")
      ->check(not_empty());
  cmd->add_flag("--paused", a.paused, "Start with time paused");
  cmd->add_option("--log", a.log, "Write event lines (reload ok/failed, captures, frame times) here, not stderr");
  cmd->add_option("--capture-dir", a.capture_dir,
                  "Write the first frame after start and after each reload as DIR/frame_<k>.png");
  cmd->add_option("--shot-dir", a.shot_dir, "Where screenshots (P, Shift+P) go (default: the current directory)");
  add_size_flag(cmd, "--shot-size", a.shot_size, "Screenshot size WxH, re-rendered (default: the window's)");
  cmd->add_option("--shot-frame", a.shot_frame, "Take both screenshots after frame N (scripts)")
      ->check(CLI::PositiveNumber);
  cmd->add_option_function<std::string>(
         "--drag", [&a](const std::string& v) { a.drag = parse_drag_flag(v); },
         "Drag TARGET (an animation target, e.g. materials[0].color, or a ranged uniform's name) to V "
         "(x or x,y,z) over frames A..B, as the panel would (scripts)")
      ->check(not_empty());
  cmd->add_option("--mesh-on-exit", a.mesh_on_exit,
                  "When the viewer closes, export the mesh as it stands (panel values, time) to FILE "
                  "(.obj, .ply, .stl, .glb, .vdb); exit 3 when that fails")
      ->check(not_empty());
  cmd->add_option("--mesh-resolution", a.mesh_resolution,
                  "Cells along the longest side of M's and --mesh-on-exit's meshes, as mesh --resolution (default 256)")
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--mesh-frame", a.mesh_frame, "Export the mesh as M does after frame N (scripts)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--exit-after", a.exit_after, "Quit after this many seconds")->check(non_negative());
  cmd->add_option("--max-frames", a.max_frames, "Quit after this many frames")->check(non_negative());
  cmd->add_option("--debounce-ms", a.debounce_ms, "Quiet time that ends a save, ms (default 10)")
      ->check(CLI::Range(0, 1000));
  cmd->add_flag("--no-panel", a.no_panel, "Start with the panel hidden (Tab shows it)");
  // A failed reload prints the compiler's whole log anyway; -v, as render's, prints it for an error that ends the run.
  cmd->add_flag("-v,--verbose", a.verbose, "Print every compile error, not the first and a count");
  add_dispatch_flag(cmd, a.dispatch,
                    "Trace the scene pass as a fragment pass (default), a compute dispatch, or auto; the window's "
                    "display pass stays fragment (docs/viewer.md#compute)");
  add_compute_group_flag(cmd, a.compute_group);
  LoadFlagChoice load;
  load.disable = load.shadertoy = false;
  load.preset_help = "Quality preset to start with, as render --preset (default: the scene's)";
  load.no_specialize_help = "Build the generic shader: every feature compiled (docs/specialization.md)";
  add_load_flags(cmd, a.load, load);
  return cmd;
}

DragFlag parse_drag_flag(const std::string& text) {
  static const std::regex form(R"(^([^=@]+)=([^@]+)@(\d{1,9})\.\.(\d{1,9})$)");
  std::smatch m;
  auto bad = [&](const std::string& why, const std::string& hint) {
    fail_input("invalid --drag '" + text + "': " + why, {}, 0, "--drag", hint);
  };
  if (!std::regex_match(text, m, form)) bad("not TARGET=V@A..B", "e.g. materials[0].color=1,0,0@5..15");
  DragFlag f;
  f.text = text;
  f.drag.target = m[1];
  f.drag.first = std::stol(m[3]);
  f.drag.last = std::stol(m[4]);
  if (f.drag.last < f.drag.first)
    bad("frame " + std::string(m[4]) + " is before " + std::string(m[3]), "A..B with A <= B");
  std::stringstream in(m[2].str());
  for (std::string part; std::getline(in, part, ',');) {
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(x)) bad("'" + part + "' is not a number", "V is x or x,y,z");
    f.values.push_back(x);
  }
  return f;
}

namespace {

// A uniform's --drag against the ranged uniforms the scene's shader
// declares as assembled now (those the panel shows as sliders).
void check_uniform_drag(const DragFlag& f, const LoadedInput& in) {
  auto bad = [&](const std::string& why, const std::string& hint) {
    fail_input("invalid --drag '" + f.text + "': " + why, {}, 0, "--drag", hint);
  };
  const std::vector<SceneParam> params = parse_scene_params(in.main().text);
  auto p = std::find_if(params.begin(), params.end(), [&](const SceneParam& q) { return q.name == f.drag.target; });
  if (p == params.end()) bad("the scene declares no ranged uniform " + f.drag.target, "a uniform with // range(a, b)");
  if (p->components > 3) bad(p->name + " is a vec4", "drag a float, int, vec2 or vec3");
  if (static_cast<int>(f.values.size()) != p->components)
    bad(p->name + " takes " + std::to_string(p->components) + (p->components == 1 ? " value" : " values"),
        "V is x or x,y,z");
  for (double v : f.values)
    if (v < p->lo || v > p->hi)
      bad(format_number(v) + " is outside " + p->name + "'s range", "V within range(" + format_number(p->lo) + ", " +
                                                                        format_number(p->hi) + ")");
}

// --drag's target and values against the scene as read now.
live::ScriptedDrag check_drag(const DragFlag& f, const fs::path& input, const SceneOverrides& set,
                              const AssembleOptions& opts) {
  auto bad = [&](const std::string& why, const std::string& hint) {
    fail_input("invalid --drag '" + f.text + "': " + why, {}, 0, "--drag", hint);
  };
  if (input.extension() != ".toml") bad("it drags a value of a scene file", "a scene .toml");
  static const std::regex ident(R"(^[A-Za-z_][A-Za-z0-9_]*$)");
  if (std::regex_match(f.drag.target, ident)) {  // no '.' nor '[': a uniform's name, not a table's value
    check_uniform_drag(f, load_input(input, {}, opts, {}, set));
    live::ScriptedDrag d = f.drag;
    d.uniform = true;
    for (size_t i = 0; i < f.values.size(); ++i) d.to[i] = f.values[i];
    return d;
  }
  Scene scene = load_scene(input, set, include_roots(input, opts));
  std::array<double, 3> cur{};
  int arity = 0;
  live::ScriptedDrag d = f.drag;
  const std::string error = target_value(scene, d.target, &cur, &arity, false);
  if (!error.empty()) bad(error, "a light, material or sky value, as [[animation]] targets");
  if (static_cast<int>(f.values.size()) != arity)
    bad(d.target + " takes " + std::to_string(arity) + (arity == 1 ? " value" : " values"), "V is x or x,y,z");
  for (size_t i = 0; i < f.values.size(); ++i) d.to[i] = f.values[i];
  return d;
}

}  // namespace

int run_view(const ViewArgs& a) {
  refuse_image_inputs({a.input});  // before any window, as render refuses it (cli/glslviewer_flags.h)
  live::ViewerOptions o;
  o.input = a.input;
  // Folded as `render` is; what the panel drags stays a uniform while it is
  // dragged (live/live_values.h). Made the initializers at every build:
  // --uniform's values, where the panel's sliders start.
  o.assemble = load_assemble_options(a.load);
  // A graph's bounds follow its box: as uniforms, a saved transform that
  // moves it recompiles nothing (docs/viewer.md#graphs).
  o.assemble.bounds_uniforms = true;
  const fs::path input = a.input;
  const AssembleOptions opts = o.assemble;
  const SceneOverrides set = a.load.overrides.set;
  // --set is applied to every read of the file: a save keeps the overrides.
  o.set = set;
  // A bad --uniform is a bad flag: exit 2 now, not an error in the window.
  // (Other assembly errors are the window's to show, and fixed by a save.)
  if (!opts.uniforms.empty()) {
    try {
      load_input(input, {}, opts, {}, set);
    } catch (const Error& e) {
      if (e.info().key.rfind("--uniform", 0) == 0) throw;
    }
  }
  if (a.size.width > 0) {
    o.width = a.size.width;
    o.height = a.size.height;
  }
  if (a.shot_size.width > 0) {
    o.shot_width = a.shot_size.width;
    o.shot_height = a.shot_size.height;
  }
  o.debug_view = a.debug_view;
  o.accumulate = a.accumulate;
  o.audio_device = a.audio_device;
  o.record.dir = a.record_dir.empty() ? fs::path(fs::path(a.input).stem().string() + "_frames") : fs::path(a.record_dir);
  o.record.fps = a.record_fps;
  if (a.record_frames) {
    o.record.first = a.record_frames->first;
    o.record.last = a.record_frames->last;
  }
  if (!a.record_video.empty()) {
    check_video_path(a.record_video);
    o.record.video = a.record_video;
  }
  o.preset = a.load.preset;
  if (a.time) o.time = *a.time;
  o.paused = a.paused;
  o.log_file = a.log;
  o.capture_dir = a.capture_dir;
  o.shot_dir = a.shot_dir;
  o.shot_frame = a.shot_frame;
  if (a.drag) o.drag = check_drag(*a.drag, input, set, opts);
  if (!a.mesh_on_exit.empty() && !mesh_format_for(a.mesh_on_exit))  // a typo is a bad flag, not a failed export
    fail_input("--mesh-on-exit '" + a.mesh_on_exit + "' is not .obj, .ply, .stl, .glb or .vdb", {}, 0,
               "--mesh-on-exit", "e.g. --mesh-on-exit part.obj");
  o.mesh_on_exit = a.mesh_on_exit;
  o.mesh_resolution = a.mesh_resolution;
  o.mesh_frame = a.mesh_frame;
  o.exit_after = a.exit_after;
  o.max_frames = a.max_frames;
  o.debounce_ms = a.debounce_ms;
  o.hide_panel = a.no_panel;
  o.dispatch.dispatch = a.dispatch;  // a bad name was refused as the flag was read
  o.dispatch.group = a.compute_group;  // auto: render's cached or measured choice (pipeline/dispatch_probe.h)
  return live::run_viewer(o);
}

}  // namespace ms
