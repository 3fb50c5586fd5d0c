// A scene file that wraps a Shadertoy shader: its [shadertoy] settings and,
// for a multi-pass shader kept as files, its [[passes]] (docs/scene-format.md):
//
//   [shadertoy]
//   common = "common.glsl"
//   media_dir = "media"
//   [[passes]]
//   type = "buffer"
//   buffer = "A"
//   file = "buffer_a.glsl"
//   iChannel0 = { buffer = "A", filter = "linear" }
//   [[passes]]
//   type = "image"
//   file = "image.glsl"
//   iChannel0 = { buffer = "A" }
//   iChannel1 = { texture = "rock.png", filter = "mipmap", wrap = "repeat" }
//
// Paths are relative to the scene file; errors name file:line and key.
#pragma once
#include <filesystem>
#include <memory>

#include <toml++/toml.h>

#include "scene/scene.h"
#include "scene/toml_read.h"

namespace ms {

// [shadertoy] into scene.shadertoy; absent: the defaults.
void read_shadertoy_settings(const Reader& r, const toml::table& root, const std::filesystem::path& scene_file,
                             ShadertoySettings& out);

// [[passes]] into a checked ShaderProject (scene/project.h); null when the
// file has none.
std::shared_ptr<const ShaderProject> read_passes(const Reader& r, const toml::table& root,
                                                 const std::filesystem::path& scene_file,
                                                 const ShadertoySettings& settings);

}  // namespace ms
