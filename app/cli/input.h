// What every subcommand starts from: a scene .toml (an SDF map or a wrapped
// Shadertoy shader) or a bare Shadertoy .glsl, loaded and assembled into
// shader source. Everything that can fail on bad input happens here, before
// any GL context exists.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shader/assemble.h"
#include "shader/preprocess.h"

namespace ms {

struct LoadedInput {
  std::filesystem::path path;  // the input as given
  Scene scene;           // a bare .glsl gets a default scene: 640x360, no tone map
  ShaderSource main;     // the main pass (assemble_input)
  bool shadertoy = false;
};

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

// `disable`: effects switched off (shadows, reflections, ao, checker-filter).
// `preset`: a quality preset replacing the scene file's (scene/quality.h);
// empty keeps the file's. The file's explicit [quality] keys still apply.
LoadedInput load_input(const std::filesystem::path& input, const std::vector<std::string>& disable,
                       const AssembleOptions& opts, const std::string& preset = {});

// load_input() in two steps, for callers whose shader depends on the scene
// (fuse_post): the scene alone (main left empty), then its main pass.
LoadedInput load_input_scene(const std::filesystem::path& input, const std::vector<std::string>& disable,
                             const std::string& preset = {});
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
