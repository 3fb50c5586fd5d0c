// Paths as the shader loaders judge them: include confinement (which
// directories an #include, a map or a Shadertoy file may read) and media
// confinement (which directories a texture, cube face, audio clip, video
// or [sky] environment may be read from), on io/path_roots.h. No GL, no
// file contents.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "io/path_roots.h"  // within_roots, describe_roots, display_path

namespace ms {

// The directories media may be read from: the scene's folder (the folder
// of `scene_file`, the .toml or the bare shader as named), `media_flag_dir`
// (--media-dir; empty: none; a scene's own media_dir is not a root: it must
// lie inside the others) and `allow_include` (--allow-include).
std::vector<std::filesystem::path> media_roots(const std::filesystem::path& scene_file,
                                               const std::filesystem::path& media_flag_dir,
                                               const std::vector<std::filesystem::path>& allow_include);

// Refuses a media file outside `roots`, judged on its canonical path
// (symlinks resolved, ".." folded) whether or not it exists, so the error
// does not tell which files exist out there. `what` names it ("texture
// 'x.png'"); `origin` and `key` place the error. Throws bad_input:
// "<what> resolves to <path>, outside the directories media may read".
void confine_media(const std::filesystem::path& file, const std::vector<std::filesystem::path>& roots,
                   const std::string& what, const std::string& origin, const std::string& key);

}  // namespace ms
