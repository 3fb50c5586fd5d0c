#include "pipeline/input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <string_view>

#include "core/error.h"
#include "gl/context.h"
#include "io/input_file.h"
#include "pipeline/bloom_setup.h"
#include "pipeline/shader_dir.h"
#include "render/environment.h"
#include "pipeline/project_passes.h"
#include "io/json_doc.h"
#include "scene/graph_alone.h"
#include "scene/load.h"
#include "scene/quality.h"
#include "core/suggest.h"
#include "preprocess/glsl_scan.h"
#include "importers/shadertoy.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

void apply_disable(Quality& q, const DisabledEffects& off) {
  if (off.shadows) q.shadows = false;
  if (off.reflections) q.reflections = false;
  if (off.ao) q.ao = false;
  if (off.checker_filter) q.checker_filter = false;
}

}  // namespace

LoadedInput load_input_scene(const fs::path& input, const DisabledEffects& disable, const AssembleOptions& opts,
                             const std::string& preset, const SceneOverrides& overrides) {
  check_input_file(input, input.extension() == ".toml" ? "scene file" : "input file");
  LoadedInput in;
  in.path = input;
  in.overrides = overrides;
  if (input.extension() == ".toml") {
    in.scene = load_scene(input, overrides, include_roots(input, opts));
  } else if (!overrides.empty()) {
    fail_input("--set needs a scene .toml: " + input.filename().string() + " has no scene keys", {}, 0,
               overrides.front().flag, "wrap the shader or graph in a scene file, or use --size, --spp and --time");
  } else if (is_graph_file(input)) {
    in.scene = graph_alone_scene(input);  // the same for every subcommand (scene/graph_alone.h)
  } else {
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
  if (disable.bloom) in.scene.bloom.enabled = false;
  return in;
}

std::vector<PassSource> assemble_passes(Scene& scene, const fs::path& input, const AssembleOptions& opts,
                                        ShaderProject& project, std::vector<std::string>& warnings,
                                        const FeatureSet* features) {
  std::vector<PassSource> passes;
  if (scene.shadertoy_file.empty() && !scene.passes) {
    PassSource scene_pass;
    scene_pass.name = scene.name;
    scene_pass.source = features ? assemble_scene(scene, opts, *features) : assemble_scene(scene, opts);
    scene_pass.uniforms = PassUniforms::scene;
    attach_environment(scene, scene_pass);  // [sky] environment: the map and its irradiance
    passes.push_back(std::move(scene_pass));
    return passes;
  }
  const fs::path wrapper = input.extension() == ".toml" ? input : fs::path{};  // includes confined to its directory
  project = scene.passes ? *scene.passes : load_shadertoy_file(scene.shadertoy_file, opts, wrapper);
  return shadertoy_passes(project, scene.shadertoy, opts, wrapper, warnings);
}

void assemble_input(LoadedInput& in, const AssembleOptions& opts) {
  in.passes = assemble_passes(in.scene, in.path, opts, in.project, in.warnings);
}

Scene read_input_scene(const fs::path& input, const AssembleOptions& opts, const SceneOverrides& overrides) {
  if (input.extension() != ".toml") {
    LoadedInput in = load_input_scene(input, {}, opts, {}, overrides);
    if (in.shadertoy) assemble_input(in, opts);  // its media and passes are checked as load_input() does
    return in.scene;
  }
  check_input_file(input, "scene file");
  Scene s = load_scene(input, overrides, include_roots(input, opts));
  if (!s.shadertoy_file.empty() || s.passes) request_zero_initialised_locals();  // as WebGL: before any context
  return s;
}

void apply_shadertoy_options(LoadedInput& in, const ShadertoyOptions& f) {
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

void report_input_warnings(const std::vector<std::string>& warnings, const std::string& input, bool strict) {
  for (const std::string& w : warnings) {
    if (strict) throw Error({Exit::threshold, input, 0, "--strict", w, {}, {}});
    std::fprintf(stderr, "marchstudio: %s: warning: %s (--strict makes this an error)\n", input.c_str(), w.c_str());
  }
}

void report_scene_notes(const Scene& scene, const std::string& input) {
  for (const std::string& n : scene.notes) std::fprintf(stderr, "marchstudio: %s: note: %s\n", input.c_str(), n.c_str());
}

std::vector<std::string> unbound_warnings(const PassGraph& graph) {
  std::vector<std::string> out;
  for (const std::string& c : graph.unbound_sampled()) out.push_back(c + " is sampled but nothing is bound to it: it reads black");
  return out;
}

LoadedInput load_input(const fs::path& input, const DisabledEffects& disable, const AssembleOptions& opts,
                       const std::string& preset, const SceneOverrides& overrides) {
  LoadedInput in = load_input_scene(input, disable, opts, preset, overrides);
  AssembleOptions o = opts;
  prepare_graph_shape(in.scene, o);
  assemble_input(in, o);
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
