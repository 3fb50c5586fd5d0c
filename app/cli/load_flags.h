// The flags that say how a scene is loaded, one group for every subcommand
// that loads one (render, its sequences and --jobs lines, mesh, bench,
// sweep, view): added by add_load_flags(), turned into a job's fields by
// set_load_fields() (or an assembler's options by load_assemble_options()).
//
//   struct MeshArgs { LoadFlags load; ... };
//   add_load_flags(cmd, a.load, {.disable = false, .shadertoy = false});
//   set_load_fields(job.frame, a.load);
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "cli/override_flags.h"
#include "pipeline/frame_job.h"
#include "pipeline/input.h"
#include "shader/assemble.h"
#include "shader/graph_interp.h"

namespace CLI {
class App;
}

namespace ms {

struct LoadFlags {
  std::string shader_dir;                 // empty: MARCH_SHADER_DIR or the built-in location
  std::vector<std::string> allow_include;  // more directories #include may read
  std::vector<std::pair<std::string, std::string>> defines;  // -D NAME[=VALUE], parsed
  std::string preset;                     // quality preset replacing the scene's; empty: the scene's
  std::vector<std::string> disable;       // effects switched off: shadows, reflections, ao, checker-filter, bloom
  bool no_specialize = false;             // the generic shader (docs/specialization.md)
  GraphEval graph_eval = GraphEval::auto_;  // --graph-eval
  bool no_prune = false;                    // --no-prune
  Overrides overrides;                    // --set, --uniform (cli/override_flags.h)
  ShadertoyOptions shadertoy;             // --media-dir, --missing-media, --mouse, --texture
};

// Which of the group a subcommand takes, and the help of the two flags
// whose words are its own.
struct LoadFlagChoice {
  bool defines = true;    // -D
  bool disable = true;    // --disable
  bool shadertoy = true;  // --media-dir, --missing-media, --mouse, --texture
  // Empty: the shared --preset (cli/common_flags.h); else this help, same check.
  std::string preset_help;
  std::string no_specialize_help =
      "Build the generic shader: every feature compiled, values as uniforms (docs/specialization.md)";
};

void add_load_flags(CLI::App* cmd, LoadFlags& f, const LoadFlagChoice& choice = {});

// The job's loading fields, each parsed or checked here: --shader-dir
// resolved, --allow-include made canonical, --disable's names, --preset,
// -D, --set, --uniform, the specialization, the graph's evaluation and
// Shadertoy's options.
void set_load_fields(FrameJob& job, const LoadFlags& f);

// The assembler's options the group asks for, for the subcommands that load
// without a FrameJob (sweep, view).
AssembleOptions load_assemble_options(const LoadFlags& f);

}  // namespace ms
