// `marchstudio info FILE...`: an image's size, channels, pixel type and
// text attributes, and the fingerprint of what made it (pipeline/fingerprint.h),
// read from the header only. `--fingerprint` prints just the fingerprint,
// for scripts; a file without one is exit 1 there. Bad files: exit 2.
// A .toml is a scene: its source, graph counts, box and bounds
// (scene/graph_scene.h scene_summary).
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ms {

struct InfoArgs {
  std::vector<std::string> files;
  bool fingerprint_only = false;
};

CLI::App* add_info_command(CLI::App& app, InfoArgs& args);
int run_info(const InfoArgs& args);

}  // namespace ms
