#include "cli/common_flags.h"

#include "cli/flag_checks.h"
#include "scene/quality.h"

namespace ms {

CLI::Option* add_backend_flag(CLI::App* cmd, std::string& backend) {
  return cmd->add_option("--backend", backend, "GL context: auto (default: EGL, else OSMesa), egl or osmesa")->check(one_of(kBackendNames));
}

CLI::Option* add_shader_dir_flag(CLI::App* cmd, std::string& dir) {
  return cmd->add_option("--shader-dir", dir, "The sdf_shaders/ directory");
}

CLI::Option* add_allow_include_flag(CLI::App* cmd, std::vector<std::string>& dirs) {
  return cmd->add_option("--allow-include", dirs,
                         "Let #include and media (textures, audio, video, [sky] environment) read files under DIR "
                         "too (default: the scene's directory and the shader dir; media: the scene's directory and "
                         "--media-dir)");
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

CLI::Option* add_compute_group_flag(CLI::App* cmd, std::string& group) {
  return cmd
      ->add_option("--compute-group", group, "Compute work group WxH (default 8x8; auto measures 8x8, 16x8, 16x16 and 32x4)")
      ->group("");
}

}  // namespace ms
