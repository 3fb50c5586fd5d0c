#include "cli/input.h"

#include "core/error.h"
#include "scene/load.h"
#include "shader/shadertoy.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

void apply_disable(Quality& q, const std::vector<std::string>& off) {
  for (const std::string& name : off) {
    if (name == "shadows") q.shadows = false;
    if (name == "reflections") q.reflections = false;
    if (name == "ao") q.ao = false;
    if (name == "checker-filter") q.checker_filter = false;
  }
}

}  // namespace

LoadedInput load_input(const fs::path& input, const std::vector<std::string>& disable, const AssembleOptions& opts) {
  std::error_code ec;
  if (!fs::is_regular_file(input, ec)) fail_input("input file not found", input.string());
  LoadedInput in;
  if (input.extension() == ".toml") {
    in.scene = load_scene(input);
  } else {
    // Shadertoy's output is display-referred: no tone map, no encode.
    in.scene.file = input;
    in.scene.name = input.stem().string();
    in.scene.shadertoy_file = input;
    in.scene.render.width = 640;
    in.scene.render.height = 360;
    in.scene.render.tonemap = Tonemap::none;
  }
  apply_disable(in.scene.quality, disable);
  in.shadertoy = !in.scene.shadertoy_file.empty();
  in.main = in.shadertoy ? assemble_shadertoy(in.scene.shadertoy_file, opts) : assemble_scene(in.scene, opts);
  return in;
}

}  // namespace ms
