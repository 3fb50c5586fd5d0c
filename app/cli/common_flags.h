// The flags several subcommands share, each defined once: its name, help
// text and check. The caller passes the field of its own Args struct.
//
//   add_backend_flag(cmd, a.backend);
//   add_shader_dir_flag(cmd, a.shader_dir);
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace ms {

// --backend auto|egl|osmesa
CLI::Option* add_backend_flag(CLI::App* cmd, std::string& backend);
// --shader-dir DIR: the sdf_shaders/ directory
CLI::Option* add_shader_dir_flag(CLI::App* cmd, std::string& dir);
// --allow-include DIR ...: more directories #include may read
CLI::Option* add_allow_include_flag(CLI::App* cmd, std::vector<std::string>& dirs);
// --preset NAME, as render and bench take it (the scene's explicit
// [quality] keys still apply)
CLI::Option* add_preset_flag(CLI::App* cmd, std::string& preset);
// --disable a,b: effects switched off
CLI::Option* add_disable_flag(CLI::App* cmd, std::vector<std::string>& effects);
// --compute-group WxH, hidden: parsed by cli/dispatch_flag.h
CLI::Option* add_compute_group_flag(CLI::App* cmd, std::string& group);

}  // namespace ms
