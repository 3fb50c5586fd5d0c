// A cubemap input's faces, found and read before any GL context
// (pipeline/project_passes.h calls this for each cubemap channel): six
// Shadertoy face files by name (io/cube_faces.h), or one equirectangular
// EXR or HDR converted to six faces, or a stand-in for missing media.
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/cube_faces.h"
#include "scene/project.h"

namespace ms {

// `where` ("Image iChannel0") and `origin` (the file) name the channel in
// errors and warnings. Face files are looked up like a texture (the
// scene's path, else the src's file name in the media directory). A
// missing face is missing media: an error naming the pass, channel and file
// unless --missing-media stands in (noise or black on every face, with a
// warning). Faces that are not square or not all one size are an error
// naming the file. Each of the six candidate files must lie inside `roots`
// (preprocess/confine.h's media_roots), symlinks resolved, or bad_input naming
// the face. `cache` reads a cubemap used twice once.
std::shared_ptr<const CubeFaces> load_cube_input(const ProjectInput& in, const ShadertoySettings& s,
                                                 const std::vector<std::filesystem::path>& roots,
                                                 const std::string& where, const std::string& origin,
                                                 std::vector<std::string>& warnings,
                                                 std::map<std::filesystem::path, std::shared_ptr<const CubeFaces>>& cache);

// The stand-in: six 64 x 64 faces of noise, byte c of texel (x, y) of face f
// the PCG hash's (as volume_noise_byte, with z = f), or 1 x 1 black faces.
CubeFaces cube_standin(MissingMedia kind);

}  // namespace ms
