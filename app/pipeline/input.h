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
#include "preprocess/preprocess.h"

namespace ms {

// Effects a job switches off (--disable): each false keeps the scene's.
struct DisabledEffects {
  bool shadows = false, reflections = false, ao = false, checker_filter = false, bloom = false;
};

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
struct ShadertoyOptions {
  std::string media_dir;
  std::optional<MissingMedia> missing_media;  // none: the scene's
  std::vector<float> mouse;   // 4 values
  double fps = 0.0;
  std::vector<NamedTexture> textures;  // --texture [NAME=]FILE, in order: u_tex0.. unless named
};
// On an SDF scene, --media-dir, --missing-media and --mouse are errors: they
// would do nothing.
void apply_shadertoy_options(LoadedInput& in, const ShadertoyOptions& f);
// Prints each of in.warnings as "marchstudio: <input>: warning: ..."; with
// `strict` the first is an error (exit 1) instead. Also the channels a
// pass samples with nothing bound, once the graph exists.
void report_input_warnings(const std::vector<std::string>& warnings, const std::string& input, bool strict);
// Under -v: each of scene.notes (how the scene was read) as
// "marchstudio: <input>: note: ...".
void report_scene_notes(const Scene& scene, const std::string& input);
// The warnings of a graph's channels sampled with nothing bound.
std::vector<std::string> unbound_warnings(const PassGraph& graph);

// An image's size in pixels (cli/input_flags.h parses "WxH"); 0x0 where
// a job means "the scene's".
struct ImageSize {
  int width = 0;
  int height = 0;
};

// `disable`: the effects switched off.
// `preset`: a quality preset replacing the scene file's (scene/quality.h);
// empty keeps the file's. The file's explicit [quality] keys still apply.
// `overrides`: --set (cli/override_flags.h), a .toml scene only; --uniform
// values travel in opts.uniforms.
LoadedInput load_input(const std::filesystem::path& input, const DisabledEffects& disable,
                       const AssembleOptions& opts, const std::string& preset = {},
                       const SceneOverrides& overrides = {});

// load_input() in two steps, for callers whose shader depends on the scene
// (fuse_post) or who apply flags to it: the scene alone (no passes), then
// its passes (for a Shadertoy input: the project read, media found). A
// graph file is read only inside include_roots(input, opts).
LoadedInput load_input_scene(const std::filesystem::path& input, const DisabledEffects& disable,
                             const AssembleOptions& opts, const std::string& preset = {},
                             const SceneOverrides& overrides = {});
void assemble_input(LoadedInput& in, const AssembleOptions& opts);

// The passes of `scene` read from `input`: an SDF scene's one pass (its
// [sky] environment attached; `features`: a specialized build's own, else
// derived), or a Shadertoy shader's buffers and Image pass with its media
// (`project` receives what it is; a .toml input confines its includes to
// its directory). The environment fills scene.sky.irradiance. What
// assemble_input() and the viewer's rebuilds call.
std::vector<PassSource> assemble_passes(Scene& scene, const std::filesystem::path& input,
                                        const AssembleOptions& opts, ShaderProject& project,
                                        std::vector<std::string>& warnings, const FeatureSet* features = nullptr);

// What the viewer reads on each save: a .toml scene parsed only (its
// shaders are assembled by each rebuild, whose errors show in the window),
// a bare Shadertoy file loaded as load_input() does. Throws ms::Error.
Scene read_input_scene(const std::filesystem::path& input, const AssembleOptions& opts,
                       const SceneOverrides& overrides);

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
