#include "cli/load_flags.h"

#include <CLI/CLI.hpp>

#include "cli/common_flags.h"
#include "cli/flag_checks.h"
#include "cli/input_flags.h"
#include "pipeline/shader_dir.h"
#include "scene/quality.h"

namespace ms {

void add_load_flags(CLI::App* cmd, LoadFlags& f, const LoadFlagChoice& choice) {
  add_shader_dir_flag(cmd, f.shader_dir);
  add_allow_include_flag(cmd, f.allow_include);
  if (choice.defines) add_define_flag(cmd, f.defines);
  if (choice.preset_help.empty())
    add_preset_flag(cmd, f.preset);
  else
    cmd->add_option("--preset", f.preset, choice.preset_help)->check(one_of(quality_preset_names()));
  if (choice.disable) add_disable_flag(cmd, f.disable);
  cmd->add_flag("--no-specialize", f.no_specialize, choice.no_specialize_help);
  add_graph_flags(cmd, f.graph_eval, f.no_prune);
  add_override_flags(cmd, f.overrides);
  if (choice.shadertoy) add_shadertoy_flags(cmd, f.shadertoy);
}

void set_load_fields(FrameJob& job, const LoadFlags& f) {
  job.shader_dir = resolve_shader_dir(f.shader_dir);
  job.allow_include = parse_allow_include(f.allow_include);
  job.defines = f.defines;
  job.specialize = f.no_specialize ? Specialization::generic : Specialization::folded;
  job.disable = parse_disabled(f.disable);
  job.preset = f.preset;
  job.set = f.overrides.set;
  job.uniforms = f.overrides.uniforms;
  job.shadertoy = f.shadertoy;
  job.graph_eval = f.graph_eval;
  job.prune = !f.no_prune;
}

AssembleOptions load_assemble_options(const LoadFlags& f) {
  AssembleOptions opts{resolve_shader_dir(f.shader_dir), f.defines, parse_allow_include(f.allow_include)};
  opts.specialize = f.no_specialize ? Specialization::generic : Specialization::folded;
  opts.graph_eval = f.graph_eval;
  opts.prune = !f.no_prune;
  opts.uniforms = f.overrides.uniforms;
  return opts;
}

}  // namespace ms
