#include "cli/input.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <string_view>

#include "cli/bloom_setup.h"
#include "cli/flag_checks.h"
#include "cli/shader_dir.h"
#include "render/environment.h"
#include "render/project_passes.h"
#include "core/error.h"
#include "gl/context.h"
#include "io/input_file.h"
#include "scene/load.h"
#include "scene/quality.h"
#include "scene/suggest.h"
#include "shader/glsl_scan.h"
#include "shader/shadertoy.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// MissingMedia's values, in its order.
const std::vector<std::string> kMissingMediaNames = {"error", "noise", "black"};

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
    if (const std::string problem = define_value_problem(value); !problem.empty())
      fail_input("the value of '" + name + "' " + problem, {}, 0, "-D", "one line, without a trailing '\\'");
    out.emplace_back(std::move(name), std::move(value));
  }
  return out;
}

AssembleOptions assemble_options(const std::string& shader_dir, const std::vector<std::string>& allow_include,
                                 bool no_specialize, const std::vector<UniformValue>& uniforms) {
  AssembleOptions opts{resolve_shader_dir(shader_dir), {}, parse_allow_include(allow_include)};
  opts.specialize = no_specialize ? Specialization::generic : Specialization::folded;
  opts.uniforms = uniforms;
  return opts;
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
                             const std::string& preset, const SceneOverrides& overrides) {
  check_input_file(input, input.extension() == ".toml" ? "scene file" : "input file");
  LoadedInput in;
  in.path = input;
  in.overrides = overrides;
  if (input.extension() == ".toml") {
    in.scene = load_scene(input, overrides);
  } else {
    if (!overrides.empty())
      fail_input("--set needs a scene .toml: " + input.filename().string() + " has no scene keys", {}, 0,
                 overrides.front().flag, "wrap the shader in a scene file, or use --size, --spp and --time");
    // Shadertoy's output is display-referred: no tone map, no encode.
    in.scene.file = input;
    in.scene.name = input.stem().string();
    in.scene.shadertoy_file = input;
    in.scene.render.width = 640;
    in.scene.render.height = 360;
    in.scene.render.tonemap = Tonemap::none;
  }
  in.shadertoy = !in.scene.shadertoy_file.empty() || in.scene.passes;
  if (in.shadertoy) request_zero_initialised_locals();  // as WebGL: before any context is made
  // Media next to the shader unless the scene or a flag says otherwise.
  if (in.shadertoy && in.scene.shadertoy.media_dir.empty()) {
    std::error_code ec;
    in.scene.shadertoy.media_dir = fs::absolute(input, ec).parent_path();
  }
  if (!preset.empty()) {
    if (in.shadertoy)
      fail_input("--preset needs an SDF scene: a Shadertoy shader has no quality settings", input.string(), 0,
                 "--preset");
    in.scene.quality = with_preset(in.scene.quality, preset);  // the file's explicit keys still win
  }
  apply_disable(in.scene.quality, disable);
  if (std::find(disable.begin(), disable.end(), "bloom") != disable.end()) in.scene.bloom.enabled = false;
  return in;
}

void assemble_input(LoadedInput& in, const AssembleOptions& opts) {
  in.passes.clear();
  if (!in.shadertoy) {
    PassSource scene_pass;
    scene_pass.name = in.scene.name;
    scene_pass.source = assemble_scene(in.scene, opts);
    scene_pass.uniforms = PassUniforms::scene;
    attach_environment(in.scene, scene_pass);  // [sky] environment: the map and its irradiance
    in.passes.push_back(std::move(scene_pass));
    return;
  }
  const fs::path wrapper = in.path.extension() == ".toml" ? in.path : fs::path{};  // includes confined to its directory
  in.project = in.scene.passes ? *in.scene.passes : load_shadertoy_file(in.scene.shadertoy_file, opts, wrapper);
  in.passes = shadertoy_passes(in.project, in.scene.shadertoy, opts, wrapper, in.warnings);
}

void apply_shadertoy_flags(LoadedInput& in, const ShadertoyFlags& f) {
  if (!in.shadertoy) {
    const char* flag = !f.media_dir.empty() ? "--media-dir" : f.missing_media ? "--missing-media"
                       : !f.mouse.empty() ? "--mouse" : !f.textures.empty() ? "--texture" : nullptr;
    if (flag)
      fail_input(std::string(flag) + " has no effect on an SDF scene", in.path.string(), 0, flag,
                 "it sets a Shadertoy shader's inputs");
  }
  ShadertoySettings& s = in.scene.shadertoy;
  if (!f.media_dir.empty()) {
    std::error_code ec;
    if (!fs::is_directory(f.media_dir, ec))
      fail_input("'" + f.media_dir + "' is not a directory", {}, 0, "--media-dir",
                 "the directory that holds Shadertoy's media files by name");
    s.media_dir = f.media_dir;
    s.media_dir_flag = f.media_dir;  // the user's own choice: media may be read from it
  }
  if (f.missing_media) s.missing_media = *f.missing_media;
  if (f.mouse.size() == 4) std::copy(f.mouse.begin(), f.mouse.end(), s.mouse);
  if (f.fps > 0) s.fps = f.fps;
  for (const NamedTexture& t : f.textures) check_input_file(t.file, "texture", "--texture");
  s.textures = f.textures;
}

MissingMedia parse_missing_media(const std::string& text) {
  for (size_t i = 0; i < kMissingMediaNames.size(); ++i)
    if (text == kMissingMediaNames[i]) return static_cast<MissingMedia>(i);
  std::vector<std::string_view> views(kMissingMediaNames.begin(), kMissingMediaNames.end());
  fail_input("'" + text + "' is not one of error, noise, black", {}, 0, "--missing-media", did_you_mean(text, views));
}

NamedTexture parse_texture_flag(const std::string& text, int unnamed_before) {
  static const std::regex named(R"(^([A-Za-z_][A-Za-z0-9_]*)=(.+)$)");
  std::smatch m;
  NamedTexture t;
  if (std::regex_match(text, m, named)) {
    t.name = m[1];
    t.file = m[2].str();
  } else {
    t.name = "u_tex" + std::to_string(unnamed_before);  // glslViewer's order for positional images
    t.file = text;
  }
  if (t.file.empty()) fail_input("invalid --texture '" + text + "'", {}, 0, "--texture", "FILE or NAME=FILE");
  std::error_code ec;
  t.file = fs::absolute(t.file, ec);
  return t;
}

void add_shadertoy_flags(CLI::App* cmd, ShadertoyFlags& f) {
  cmd->add_option("--media-dir", f.media_dir,
                  "Where a Shadertoy shader's media (/media/a/<name>) are found, by file name (default: the shader's "
                  "directory, or the scene's [shadertoy] media_dir)")
      ->check(not_empty());
  cmd->add_option_function<std::string>(
         "--missing-media", [&f](const std::string& v) { f.missing_media = parse_missing_media(v); },
         "For a texture not in the media directory: error (default), noise or black stand-ins, with a warning")
      ->check(one_of(kMissingMediaNames));
  cmd->add_option_function<std::string>(
         "--mouse", [&f](const std::string& v) { f.mouse = parse_mouse_flag(v); },
         "iMouse of a Shadertoy shader: X,Y,Z,W in pixels, or u_mouse of a glslViewer shader: X,Y (default: the scene's, "
         "else 0,0,0,0)");
  cmd->add_option_function<std::vector<std::string>>(
         "--texture",
         [&f](const std::vector<std::string>& v) {
           int unnamed = 0;  // FILE alone: glslViewer's positional order, u_tex0, u_tex1, ..
           for (const std::string& one : v) {
             f.textures.push_back(parse_texture_flag(one, unnamed));
             const std::string& name = f.textures.back().name;
             if (one.compare(0, name.size() + 1, name + "=") != 0) ++unnamed;
           }
         },
         "A glslViewer shader's texture: FILE binds u_tex0, u_tex1, .. in order; NAME=FILE binds the sampler2D NAME "
         "(repeatable)")
      ->allow_extra_args(false)
      ->type_size(1)
      ->expected(1, CLI::detail::expected_max_vector_size);
}

void report_input_warnings(const std::vector<std::string>& warnings, const std::string& input, bool strict) {
  for (const std::string& w : warnings) {
    if (strict) throw Error({Exit::threshold, input, 0, "--strict", w, {}, {}});
    std::fprintf(stderr, "marchstudio: %s: warning: %s (--strict makes this an error)\n", input.c_str(), w.c_str());
  }
}

std::vector<std::string> unbound_warnings(const PassGraph& graph) {
  std::vector<std::string> out;
  for (const std::string& c : graph.unbound_sampled()) out.push_back(c + " is sampled but nothing is bound to it: it reads black");
  return out;
}

std::vector<float> parse_mouse_flag(const std::string& text) {
  std::vector<float> v;
  size_t at = 0;
  const char* hint = "X,Y (glslViewer's u_mouse) or X,Y,Z,W (Shadertoy's iMouse), in pixels";
  while (at <= text.size() && v.size() < 5) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string part = text.substr(at, comma - at);
    char* end = nullptr;
    const double d = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(d) || std::abs(d) > 1e9)
      fail_input("invalid --mouse '" + text + "'", {}, 0, "--mouse", hint);
    v.push_back(static_cast<float>(d));
    at = comma + 1;
  }
  if (v.size() == 2) v.resize(4, 0.0f);  // a position alone: no click
  if (v.size() != 4) fail_input("invalid --mouse '" + text + "'", {}, 0, "--mouse", hint);
  return v;
}

LoadedInput load_input(const fs::path& input, const std::vector<std::string>& disable, const AssembleOptions& opts,
                       const std::string& preset, const SceneOverrides& overrides) {
  LoadedInput in = load_input_scene(input, disable, preset, overrides);
  assemble_input(in, opts);
  return in;
}

bool fuse_post(const LoadedInput& in, int spp, bool aovs, bool encode_srgb, AssembleOptions& opts) {
  if (in.shadertoy || spp != 1 || aovs || bloom_on(in, encode_srgb)) return false;  // bloom reads the accumulation
  for (auto& d : fused_post_defines(in.scene.render.tonemap, encode_srgb)) opts.defines.push_back(std::move(d));
  return true;
}

ShaderSource assemble_still(LoadedInput& in, AssembleOptions& opts, int spp, bool aovs, bool display, bool& fused) {
  in.scene.bloom.enabled = bloom_on(in, display);  // from here on: whether this output blooms
  fused = fuse_post(in, spp, aovs, display, opts);
  assemble_input(in, opts);
  // Shadertoy output is display-referred already: never encoded again.
  return assemble_post(in.scene.render.tonemap, display && !in.shadertoy, opts, in.shadertoy, bloom_on(in, display));
}

}  // namespace ms
