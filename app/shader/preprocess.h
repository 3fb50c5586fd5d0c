// marchstudio's own GLSL preprocessor: expands `#include`, honours
// `#pragma once`, and emits `#line` directives so that every line the driver
// reports maps back to the file and line it came from. No GL here.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ms {

// Line numbers are emitted as `#line N*kLineStride+L N` for line L of source
// string N (the root, N=0, keeps plain numbers): Mesa reports string 0 for
// every error found after parsing (its YYLLOC_DEFAULT zeroes `source`), so
// the file must be recoverable from the line number alone. parse_info_log()
// decodes this; a file may have at most kLineStride-2 lines.
inline constexpr int kLineStride = 100000;

struct ShaderSource {
  std::string text;                                 // assembled GLSL with #line directives
  std::vector<std::string> files;                   // source-string number N -> display path (N=0: the root)
  std::vector<std::filesystem::path> dependencies;  // every file read, canonical, in first-read order
};

struct PreprocessOptions {
  std::vector<std::filesystem::path> include_dirs;  // searched after the including file's own dir
  // Confinement: when not empty, an #include may only read files inside
  // these directories, judged on the canonical path (symlinks and ".."
  // resolved), so a scene cannot pull /etc/passwd or ~/.ssh into a shader
  // and have the compiler echo it. assemble.h sets the scene's directory,
  // sdf_shaders/ and --allow-include; empty: unconfined (tests, tools).
  std::vector<std::filesystem::path> roots;
};

// Expand `#include "file"` (and `#include <file>`, searched in include_dirs
// only) recursively in `root_text`. The root is shown as `root_name` in
// errors and is source string 0; its relative includes resolve against
// root_dir, then include_dirs. Absolute include paths are allowed.
// Throws ms::Error (bad_input) for cycles, missing includes, a #version in an
// included file, malformed #include lines and (with opts.roots) an include
// outside the roots, located at file:line. That error names the path and
// is raised before the file is opened: none of its content is ever shown.
ShaderSource preprocess(std::string_view root_text, const std::string& root_name,
                        const std::filesystem::path& root_dir, const PreprocessOptions& opts);

// Whether `p`, made absolute with symlinks resolved as far as it exists,
// lies inside one of `roots` (themselves canonicalised).
bool within_roots(const std::filesystem::path& p, const std::vector<std::filesystem::path>& roots);

// "a, b and c" of display paths, for hints naming the allowed roots.
std::string describe_roots(const std::vector<std::filesystem::path>& roots);

// How a path is shown to users: relative to the current directory when it
// lies under it, else absolute; always with '/' separators. Empty stays empty.
std::string display_path(const std::filesystem::path& p);

}  // namespace ms
