// Paths as the shader loaders judge and show them: include confinement
// (which directories an #include, a map or a Shadertoy file may read),
// media confinement (which directories a texture, cube face, audio clip,
// video or [sky] environment may be read from) and the display form of a
// path in errors. No GL, no file contents.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace ms {

// Whether `p`, made absolute with symlinks resolved as far as it exists,
// lies inside one of `roots` (themselves canonicalised).
bool within_roots(const std::filesystem::path& p, const std::vector<std::filesystem::path>& roots);

// "a, b and c" of display paths, for hints naming the allowed roots.
std::string describe_roots(const std::vector<std::filesystem::path>& roots);

// How a path is shown to users: relative to the current directory when it
// lies under it, else absolute; always with '/' separators. Empty stays empty.
std::string display_path(const std::filesystem::path& p);

// Absolute, symlinks resolved as far as the path exists, ".." folded.
std::filesystem::path resolved_path(const std::filesystem::path& p);

// Whether canonical path `p` lies inside one of `canonical_roots`.
bool inside_roots(const std::filesystem::path& canonical, const std::vector<std::filesystem::path>& canonical_roots);

// `roots` made canonical (resolved_path), empty ones dropped.
std::vector<std::filesystem::path> resolved_roots(const std::vector<std::filesystem::path>& roots);

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
