#include "cli/input.h"

#include <regex>

#include "core/error.h"
#include "io/input_file.h"
#include "scene/load.h"
#include "scene/quality.h"
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

ImageSize parse_size_flag(const std::string& text, const std::string& flag) {
  static const std::regex re(R"(^\s*(\d{1,9})\s*[xX]\s*(\d{1,9})\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    fail_input("invalid size '" + text + "'", {}, 0, flag, "expected WxH, e.g. 1280x720");
  ImageSize out{std::stoi(m[1]), std::stoi(m[2])};
  if (out.width < 1 || out.height < 1) fail_input("image size " + text + " must be at least 1x1", {}, 0, flag);
  return out;
}

std::vector<std::pair<std::string, std::string>> parse_defines(const std::vector<std::string>& flags) {
  static const std::regex ident(R"(^[A-Za-z_][A-Za-z0-9_]*$)");
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& f : flags) {
    const size_t eq = f.find('=');
    std::string name = f.substr(0, eq), value = eq == std::string::npos ? "1" : f.substr(eq + 1);
    if (!std::regex_match(name, ident))
      fail_input("'" + name + "' is not a GLSL identifier", {}, 0, "-D", "use -D NAME or -D NAME=VALUE");
    if (value.find_first_of("\r\n") != std::string::npos)
      fail_input("the value of '" + name + "' spans lines", {}, 0, "-D");
    out.emplace_back(std::move(name), std::move(value));
  }
  return out;
}

std::vector<fs::path> parse_allow_include(const std::vector<std::string>& flags) {
  std::vector<fs::path> dirs;
  for (const std::string& f : flags) {
    std::error_code ec;
    if (f.empty() || !fs::is_directory(f, ec))
      fail_input("'" + f + "' is not a directory", {}, 0, "--allow-include",
                 "--allow-include DIR lets #include read files under DIR");
    dirs.push_back(fs::canonical(f, ec));
  }
  return dirs;
}

LoadedInput load_input_scene(const fs::path& input, const std::vector<std::string>& disable,
                             const std::string& preset) {
  check_input_file(input, input.extension() == ".toml" ? "scene file" : "input file");
  LoadedInput in;
  in.path = input;
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
  in.shadertoy = !in.scene.shadertoy_file.empty();
  if (!preset.empty()) {
    if (in.shadertoy)
      fail_input("--preset needs an SDF scene: a Shadertoy shader has no quality settings", input.string(), 0,
                 "--preset");
    in.scene.quality = with_preset(in.scene.quality, preset);  // the file's explicit keys still win
  }
  apply_disable(in.scene.quality, disable);
  return in;
}

void assemble_input(LoadedInput& in, const AssembleOptions& opts) {
  const bool wrapped = in.path.extension() == ".toml";  // includes confined to the .toml's directory
  in.main = in.shadertoy ? assemble_shadertoy(in.scene.shadertoy_file, opts, wrapped ? in.path : fs::path{})
                         : assemble_scene(in.scene, opts);
}

LoadedInput load_input(const fs::path& input, const std::vector<std::string>& disable, const AssembleOptions& opts,
                       const std::string& preset) {
  LoadedInput in = load_input_scene(input, disable, preset);
  assemble_input(in, opts);
  return in;
}

bool fuse_post(const LoadedInput& in, int spp, bool aovs, bool encode_srgb, AssembleOptions& opts) {
  if (in.shadertoy || spp != 1 || aovs) return false;
  for (auto& d : fused_post_defines(in.scene.render.tonemap, encode_srgb)) opts.defines.push_back(std::move(d));
  return true;
}

ShaderSource assemble_still(LoadedInput& in, AssembleOptions& opts, int spp, bool aovs, bool display, bool& fused) {
  fused = fuse_post(in, spp, aovs, display, opts);
  assemble_input(in, opts);
  // Shadertoy output is display-referred already: never encoded again.
  return assemble_post(in.scene.render.tonemap, display && !in.shadertoy, opts);
}

}  // namespace ms
