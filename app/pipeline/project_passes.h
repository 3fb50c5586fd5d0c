// A Shadertoy project's passes as render/graph.h takes them, before any GL
// context: each pass assembled, each texture found (the scene's path, or
// /media/a/<name> in the media directory by its file name) and decoded
// (io/), missing media refused or stood in for. `render` (pipeline/input.h) and
// the viewer (live/session.h) load through this one function.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "render/graph.h"
#include "scene/project.h"
#include "shader/assemble.h"
#include "importers/shadertoy_media.h"

namespace ms {

// `scene_file`: the .toml that wraps the project (empty for a bare file).
// Media are looked up in s.media_dir, else the folder of the scene (or the
// bare file), and read only inside preprocess/confine.h's media_roots.
// Warnings (stand-ins, a second shader in a JSON array) go to `warnings`.
// Throws bad_input: a missing texture names the pass, the channel and the
// src; so does a volume that is not one of Shadertoy's two noise volumes
// (volumes are never read from files: a known one is missing media, stood in
// for by --missing-media); an input type marchstudio does not run names what it is.
std::vector<PassSource> shadertoy_passes(const ShaderProject& p, const ShadertoySettings& s,
                                         const AssembleOptions& opts, const std::filesystem::path& scene_file,
                                         std::vector<std::string>& warnings);

// The stand-in for a missing texture: Shadertoy's noise textures by their
// size and channels, generated from a fixed seed (not Shadertoy's pixels),
// any other as 256x256 RGBA noise; or 1x1 black.
Image media_standin(const std::string& src, MissingMedia kind);

// Byte `c` (0..3) of voxel (x, y, z) of a volume stand-in `size` on a side:
// byte c (lowest first) of pcg_hash(x + size * (y + size * z)), the PCG hash
// of Jarzynski and Olano (JCGT 2020). A one-channel volume keeps byte 0.
std::uint8_t volume_noise_byte(int x, int y, int z, int c, int size);

// The stand-in for one of Shadertoy's volumes (`m.volume`): noise_size^3
// voxels of volume_noise_byte with its channel count (not Shadertoy's
// voxels), or one black voxel.
Volume volume_standin(const ShadertoyMedia& m, MissingMedia kind);

}  // namespace ms
