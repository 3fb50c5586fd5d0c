// `marchstudio bench SCENE`: frame times, startup times and per-pixel cost
// of a scene, as a table or one JSON object (docs/bench.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cli/load_flags.h"
#include "gl/context.h"
#include "pipeline/input.h"
#include "render/compute_frame.h"
#include "shader/compute_wrap.h"

namespace CLI {
class App;
}

namespace ms {

struct BenchArgs {
  std::string input;       // a scene .toml, or a Shadertoy shader (its passes timed, no cost counted)
  ImageSize size;          // --size WxH; 0x0: the scene's
  int frames = 30;
  int warmup = 3;
  int spp = 0;             // 0: the scene's
  bool json = false;
  bool shader_cache = false;  // let the driver's disk cache serve the compile
  Backend backend = Backend::automatic;
  LoadFlags load;  // no -D (cli/load_flags.h)
  bool strict = false;     // any NaN/Inf pixel in the counting pass is an error (exit 1)
  Dispatch dispatch = Dispatch::fragment;  // --dispatch fragment|compute|auto (cli/dispatch_flag.h)
  std::optional<ComputeGroup> compute_group;  // hidden --compute-group; none: 8x8, or auto's measured group
  bool verbose = false;               // -v: what --dispatch auto chose, and why
};

CLI::App* add_bench_command(CLI::App& app, BenchArgs& args);
int run_bench_command(const BenchArgs& args);

}  // namespace ms
