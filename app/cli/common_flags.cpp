#include "cli/common_flags.h"

#include "cli/dispatch_flag.h"
#include "cli/flag_checks.h"
#include "cli/input_flags.h"
#include "scene/quality.h"

namespace ms {

CLI::Option* add_backend_flag(CLI::App* cmd, Backend& backend) {
  return cmd
      ->add_option_function<std::string>(
          "--backend", [&backend](const std::string& v) { backend = parse_backend(v); },
          "GL context: auto (default: EGL, else OSMesa), egl or osmesa")
      ->check(one_of(kBackendNames));
}

CLI::Option* add_shader_dir_flag(CLI::App* cmd, std::string& dir) {
  return cmd->add_option("--shader-dir", dir, "The sdf_shaders/ directory");
}

CLI::Option* add_allow_include_flag(CLI::App* cmd, std::vector<std::string>& dirs) {
  return cmd->add_option("--allow-include", dirs,
                         "Let #include (and scene.map, scene.graph, scene.shadertoy) and media (textures, audio, "
                         "video, [sky] environment) read files under DIR too (default: the scene's directory and the "
                         "shader dir; media: the scene's directory and --media-dir)");
}

CLI::Option* add_preset_flag(CLI::App* cmd, std::string& preset) {
  return cmd
      ->add_option("--preset", preset,
                   "Quality preset: fast, balanced, reference or textbook (default: the scene's; its explicit "
                   "[quality] keys still apply)")
      ->check(one_of(quality_preset_names()));
}

CLI::Option* add_disable_flag(CLI::App* cmd, std::vector<std::string>& effects) {
  return cmd->add_option("--disable", effects, "Switch effects off: shadows, reflections, ao, checker-filter, bloom")
      ->delimiter(',')
      ->check(one_of(kEffectNames));
}

CLI::Option* add_size_flag(CLI::App* cmd, const std::string& name, ImageSize& size, const std::string& description) {
  return cmd->add_option_function<std::string>(
      name, [name, &size](const std::string& v) { size = parse_size_flag(v, name); }, description);
}

CLI::Option* add_dispatch_flag(CLI::App* cmd, Dispatch& dispatch, const std::string& description,
                               const std::string& choices) {
  return add_enum_flag(cmd, "--dispatch", dispatch, parse_dispatch, choices, description);
}

void add_graph_flags(CLI::App* cmd, GraphEval& eval, bool& no_prune) {
  add_enum_flag(cmd, "--graph-eval", eval, parse_graph_eval, "inline|interpreter|auto",
                "A graph scene's map(): straight GLSL, the interpreter over node buffers, or by size (default; "
                "docs/scene-graph.md)");
  cmd->add_flag("--no-prune", no_prune,
                "Evaluate a graph scene's whole graph everywhere: the brute-force reference of the pruned grid");
}

CLI::Option* add_define_flag(CLI::App* cmd, std::vector<std::pair<std::string, std::string>>& defines) {
  return cmd->add_option_function<std::vector<std::string>>(
      "-D,--define",
      [&defines](const std::vector<std::string>& v) {
        for (auto& d : parse_defines(v)) defines.push_back(std::move(d));
      },
      "Inject #define NAME VALUE into the scene shader (NAME or NAME=VALUE)");
}

CLI::Option* add_compute_group_flag(CLI::App* cmd, std::optional<ComputeGroup>& group) {
  return cmd
      ->add_option_function<std::string>(
          "--compute-group", [&group](const std::string& v) { group = parse_compute_group(v); },
          "Compute work group WxH (default 8x8; auto measures 8x8, 16x8, 16x16 and 32x4)")
      ->group("");
}

}  // namespace ms
