// Paths judged against the directories a run may read (roots), and the
// form a path takes in errors. The scene loader confines a graph file with
// these; preprocess/confine.h builds the include and media rules on them.
// No file contents are read.
//
//   if (!within_roots(file, roots)) fail_input("... outside ...", ..., "allowed: " + describe_roots(roots));
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

}  // namespace ms
