// A Shadertoy project's passes as render/graph.h takes them, before any GL
// context: each pass assembled, each texture found (the scene's path, or
// /media/a/<name> in the media directory by its file name) and decoded
// (io/), missing media refused or stood in for. `render` (cli/input.h) and
// the viewer (live/session.h) load through this one function.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "render/graph.h"
#include "shader/assemble.h"
#include "shader/project.h"

namespace ms {

// `scene_file`: the .toml that wraps the project (empty for a bare file).
// Warnings (stand-ins, a second shader in a JSON array) go to `warnings`.
// Throws bad_input: a missing texture names the pass, the channel and the
// src; an input type marchstudio does not run names what it is.
std::vector<PassSource> shadertoy_passes(const ShaderProject& p, const ShadertoySettings& s,
                                         const AssembleOptions& opts, const std::filesystem::path& scene_file,
                                         std::vector<std::string>& warnings);

// The stand-in for a missing texture: Shadertoy's noise textures by their
// size and channels, generated from a fixed seed (not Shadertoy's pixels),
// any other as 256x256 RGBA noise; or 1x1 black.
Image media_standin(const std::string& src, MissingMedia kind);

}  // namespace ms
