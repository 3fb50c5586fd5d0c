// `marchstudio sweep SCENE`: frame time against error over a grid of quality
// settings, written as CSV, JSON and a plot (docs/speed-vs-error.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "sweep/sweep.h"
#include "sweep/sweep_grid.h"
#include "cli/load_flags.h"
#include "gl/context.h"
#include "pipeline/input.h"
#include "render/compute_frame.h"
#include "shader/compute_wrap.h"

namespace CLI {
class App;
}

namespace ms {

struct SweepArgs {
  std::string input;          // a scene .toml with an SDF map
  ImageSize size{640, 360};  // --size WxH
  int frames = 5;
  int rounds = 3;
  int warmup = 1;
  int spp = 1;
  int ref_spp = 16;
  SweepGrid grid = SweepGrid::quick;
  std::optional<SweepClock> time_by;  // the clock of the fronts and the plot; none: auto
  std::vector<std::string> only;    // row names to keep (empty: the whole grid)
  std::string out = ".";            // directory for <scene>.sweep.{csv,json,png}
  Backend backend = Backend::automatic;
  LoadFlags load = [] {  // no -D, --disable or Shadertoy options (cli/load_flags.h)
    LoadFlags f;
    f.preset = "balanced";  // the rows vary the settings around this preset
    return f;
  }();
  bool quiet = false;
  Dispatch dispatch = Dispatch::fragment;  // --dispatch fragment|compute|auto (cli/dispatch_flag.h)
  std::optional<ComputeGroup> compute_group;  // hidden --compute-group; none: 8x8, or auto's measured group
};

CLI::App* add_sweep_command(CLI::App& app, SweepArgs& args);
int run_sweep_command(const SweepArgs& args);

}  // namespace ms
