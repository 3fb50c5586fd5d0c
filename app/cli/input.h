// What every subcommand starts from: a scene .toml (an SDF map, a wrapped
// Shadertoy shader or [[passes]]), a bare Shadertoy .glsl or Shadertoy's
// JSON, loaded and assembled into the passes of a graph (render/graph.h).
// Everything that can fail on bad input happens here, before any GL
// context exists: shaders, media, flags.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/graph.h"
#include "scene/overrides.h"
#include "scene/scene.h"
#include "shader/assemble.h"
#include "shader/preprocess.h"

namespace CLI {
class App;
}

namespace ms {

struct LoadedInput {
  std::filesystem::path path;  // the input as given
  Scene scene;           // a bare .glsl or .json gets a default scene: 640x360, no tone map
  bool shadertoy = false;
  ShaderProject project;            // shadertoy: what its passes are (assemble_input)
  std::vector<PassSource> passes;   // assembled: a scene's one pass, or the buffers then the Image
  std::vector<std::string> warnings;  // for the subcommand to print (missing media stood in for, ...)
  SceneOverrides overrides;  // --set, applied to the scene file (the fingerprint hashes them)

  // The pass that draws the frame (the scene's, or the Image pass).
  const ShaderSource& main() const { return passes.back().source; }
  // Buffers carry state from frame to frame: a still replays frames 0..N.
  bool stateful() const { return passes.size() > 1; }
};

// Shadertoy flags over a scene file's [shadertoy] (empty/negative: keep).
struct ShadertoyFlags {
  std::string media_dir;
  std::optional<MissingMedia> missing_media;  // none: the scene's
  std::vector<float> mouse;   // 4 values
  double fps = 0.0;
  std::vector<NamedTexture> textures;  // --texture [NAME=]FILE, in order: u_tex0.. unless named
};
// On an SDF scene, --media-dir, --missing-media and --mouse are errors: they
// would do nothing.
void apply_shadertoy_flags(LoadedInput& in, const ShadertoyFlags& f);
// --media-dir, --missing-media and --mouse on a subcommand (--fps is its own).
void add_shadertoy_flags(CLI::App* cmd, ShadertoyFlags& f);
// Prints each of in.warnings as "marchstudio: <input>: warning: ..."; with
// `strict` the first is an error (exit 1) instead. Also the channels a
// pass samples with nothing bound, once the graph exists.
void report_input_warnings(const std::vector<std::string>& warnings, const std::string& input, bool strict);
// The warnings of a graph's channels sampled with nothing bound.
std::vector<std::string> unbound_warnings(const PassGraph& graph);
// "X,Y,Z,W" as iMouse, or "X,Y" (glslViewer's u_mouse; Z and W 0). Throws
// bad_input naming --mouse.
std::vector<float> parse_mouse_flag(const std::string& text);
// "error", "noise" or "black" (--missing-media). Throws bad_input naming
// the flag, with a did-you-mean.
MissingMedia parse_missing_media(const std::string& text);
// One --texture: "NAME=FILE" binds NAME, "FILE" binds u_tex<unnamed_before>;
// the file made absolute (it is checked when applied).
NamedTexture parse_texture_flag(const std::string& text, int unnamed_before);

// A "WxH" flag value (render/bench --size, view --size/--shot-size); each
// side at least 1. Whether the GL can make it is checked later, with a context.
struct ImageSize {
  int width = 0;
  int height = 0;
};
ImageSize parse_size_flag(const std::string& text, const std::string& flag = "--size");

// "NAME" or "NAME=VALUE" flags as (name, value) #defines; NAME must be a
// GLSL identifier, VALUE one line. Throws bad_input naming -D.
std::vector<std::pair<std::string, std::string>> parse_defines(const std::vector<std::string>& flags);

// --allow-include DIR flags: each an existing directory, made canonical
// (AssembleOptions::allow_include). Throws bad_input naming the flag.
std::vector<std::filesystem::path> parse_allow_include(const std::vector<std::string>& flags);

// The assembler's options from the flags bench, sweep and sequences share:
// --shader-dir, --allow-include, --no-specialize (otherwise folded to the
// scene; animated values stay uniforms) and the --uniform values.
AssembleOptions assemble_options(const std::string& shader_dir, const std::vector<std::string>& allow_include,
                                 bool no_specialize, const std::vector<UniformValue>& uniforms);

// `disable`: effects switched off (shadows, reflections, ao, checker-filter, bloom).
// `preset`: a quality preset replacing the scene file's (scene/quality.h);
// empty keeps the file's. The file's explicit [quality] keys still apply.
// `overrides`: --set (cli/override_flags.h), a .toml scene only; --uniform
// values travel in opts.uniforms.
LoadedInput load_input(const std::filesystem::path& input, const std::vector<std::string>& disable,
                       const AssembleOptions& opts, const std::string& preset = {},
                       const SceneOverrides& overrides = {});

// load_input() in two steps, for callers whose shader depends on the scene
// (fuse_post) or who apply flags to it: the scene alone (no passes), then
// its passes (for a Shadertoy input: the project read, media found).
LoadedInput load_input_scene(const std::filesystem::path& input, const std::vector<std::string>& disable,
                             const std::string& preset = {}, const SceneOverrides& overrides = {});
void assemble_input(LoadedInput& in, const AssembleOptions& opts);

// Frames of one sample without AOVs need no accumulation buffer and no post
// pass: for an SDF scene, adds fused_post_defines() (shader/assemble.h) to
// opts and returns true; the frames must then set FrameParams::fused_post.
bool fuse_post(const LoadedInput& in, int spp, bool aovs, bool encode_srgb, AssembleOptions& opts);

// The programs of a still (or of each frame of a sequence) as `render`
// builds them for an output stored as 8-bit display values (`display`) or
// as float: fuse_post(), then the main pass into in.main, and the post pass
// returned. `fused` receives FrameParams::fused_post. `render` and `test`
// both build their programs here.
ShaderSource assemble_still(LoadedInput& in, AssembleOptions& opts, int spp, bool aovs, bool display, bool& fused);

}  // namespace ms
