#include "cli/info_cmd.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "io/image_io.h"
#include "scene/graph_alone.h"
#include "scene/graph_scene.h"
#include "scene/load.h"
#include "scene/toml_read.h"  // printable(): one line per attribute

namespace ms {

CLI::App* add_info_command(CLI::App& app, InfoArgs& a) {
  CLI::App* cmd = app.add_subcommand("info", "Print an image's size, channels, metadata and fingerprint, or a scene's or graph file's source, graph, bounds and Lipschitz factor");
  cmd->add_option("files", a.files, "Image files (PNG, JPEG, TIFF, EXR, ...), scene files (.toml) or graph files (.json)")->required();
  cmd->add_flag("--fingerprint", a.fingerprint_only,
                "Print only each file's fingerprint (exit 1 when one has none)");
  return cmd;
}

int run_info(const InfoArgs& a) {
  int status = 0;
  for (const std::string& f : a.files) {
    if (!a.fingerprint_only && std::filesystem::path(f).extension() == ".toml") {
      for (const std::string& line : scene_summary(load_scene(f))) std::printf("%s\n", line.c_str());
      continue;
    }
    if (!a.fingerprint_only && is_graph_file(f)) {
      for (const std::string& line : scene_summary(graph_alone_scene(f))) std::printf("%s\n", line.c_str());
      continue;
    }
    const ImageInfo info = read_image_info(f);
    if (a.fingerprint_only) {
      if (info.fingerprint.empty()) {
        std::fprintf(stderr, "marchstudio: %s: no marchstudio fingerprint\n", f.c_str());
        status = static_cast<int>(Exit::threshold);
      } else {
        if (a.files.size() > 1) std::printf("%s  %s\n", info.fingerprint.c_str(), f.c_str());
        else std::printf("%s\n", info.fingerprint.c_str());
      }
      continue;
    }
    std::string channels;
    for (const std::string& c : info.channels) channels += (channels.empty() ? "" : ",") + c;
    std::printf("%s: %dx%d, %zu channels (%s), %s, %s\n", f.c_str(), info.width, info.height, info.channels.size(),
                channels.c_str(), info.pixel_type.c_str(), info.format.c_str());
    std::printf("  fingerprint: %s\n", info.fingerprint.empty() ? "none" : info.fingerprint.c_str());
    for (const auto& [k, v] : info.attributes)
      if (k != kFingerprintKey) std::printf("  %s: %s\n", printable(k, 80).c_str(), printable(v, 400).c_str());
  }
  return status;
}

}  // namespace ms
