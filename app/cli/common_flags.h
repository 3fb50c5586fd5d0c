// The flags several subcommands share, each defined once: its name, help
// text and check. The caller passes the field of its own Args struct.
//
//   add_backend_flag(cmd, a.backend);
//   add_shader_dir_flag(cmd, a.shader_dir);
#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/context.h"
#include "pipeline/input.h"
#include "render/compute_frame.h"
#include "shader/compute_wrap.h"

namespace ms {

// --backend auto|egl|osmesa, typed as it is read
CLI::Option* add_backend_flag(CLI::App* cmd, Backend& backend);
// --shader-dir DIR: the sdf_shaders/ directory
CLI::Option* add_shader_dir_flag(CLI::App* cmd, std::string& dir);
// --allow-include DIR ...: more directories #include may read
CLI::Option* add_allow_include_flag(CLI::App* cmd, std::vector<std::string>& dirs);
// --preset NAME, as render and bench take it (the scene's explicit
// [quality] keys still apply)
CLI::Option* add_preset_flag(CLI::App* cmd, std::string& preset);
// --disable a,b: effects switched off
CLI::Option* add_disable_flag(CLI::App* cmd, std::vector<std::string>& effects);
// A WxH flag (--size, --shot-size), typed as it is read: parse_size_flag,
// whose error names `name`. Not given: `size` keeps its default.
CLI::Option* add_size_flag(CLI::App* cmd, const std::string& name, ImageSize& size, const std::string& description);
// An enum flag typed as it is read: `parse` turns a name into the value and
// throws its own one-line error, naming the flag, for anything else;
// --help lists `choices`, e.g. "{default, idiff}".
template <class E>
CLI::Option* add_enum_flag(CLI::App* cmd, const std::string& name, E& value, E (*parse)(const std::string&),
                           const std::string& choices, const std::string& description) {
  return cmd
      ->add_option_function<std::string>(
          name, [&value, parse](const std::string& v) { value = parse(v); }, description)
      ->check(CLI::Validator(
          [parse](std::string& v) {
            (void)parse(v);  // a bad name throws here, before any callback
            return std::string();
          },
          choices));
}
// --graph-eval NAME and --no-prune: how a graph scene's map() is evaluated
// (docs/scene-graph.md).
void add_graph_flags(CLI::App* cmd, GraphEval& eval, bool& no_prune);
// --dispatch NAME, typed as it is read (cli/dispatch_flag.h's
// parse_dispatch, whose one-line error a bad name gets); --help lists
// `choices`.
CLI::Option* add_dispatch_flag(CLI::App* cmd, Dispatch& dispatch, const std::string& description,
                               const std::string& choices = "{fragment, compute, auto}");
// -D,--define NAME[=VALUE], repeatable, parsed as it is read
// (parse_defines) and added after `defines`' own.
CLI::Option* add_define_flag(CLI::App* cmd, std::vector<std::pair<std::string, std::string>>& defines);
// --compute-group WxH, hidden, typed as it is read (parse_compute_group);
// none when not given.
CLI::Option* add_compute_group_flag(CLI::App* cmd, std::optional<ComputeGroup>& group);

}  // namespace ms
