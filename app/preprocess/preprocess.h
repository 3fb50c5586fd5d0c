// marchstudio's own GLSL preprocessor: expands `#include`, honours
// `#pragma once` and include guards, and emits `#line` directives so that
// every line the driver reports maps back to the file and line it came
// from. Alongside, preprocess/macro_engine.h models the driver's own
// preprocessor over the result: the shader's size, its macro expansion and
// its expression depth are bounded, and a live `#error` fails here. No GL.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "preprocess/confine.h"
#include "preprocess/macro_engine.h"

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
  // Sources that are not files: `#include "NAME"` of a key here reads its
  // text, shown in errors as `display`; its own includes resolve in `dir`.
  // Shadertoy passes come this way (inline JSON code, or a file's text
  // after importers/es_compat.h's renames). Not confined: the caller read them.
  struct InlineFile {
    std::string display;
    std::string text;
    std::filesystem::path dir;
  };
  std::map<std::string, InlineFile> inline_files;
  // The budgets (macro_engine.h). The text size holds in any case.
  PreprocessLimits limits;
  // Model the driver's preprocessor: conditionals (an #include in a dead
  // #if group is skipped), macro and depth budgets, #error. Off only for
  // text that is never compiled (the library scan of assemble.cpp).
  bool model_driver = true;
};

// An #include chain may be this many files deep, counting from the first
// file the root includes (a scene's map, a Shadertoy shader) as 1.
inline constexpr int kMaxIncludeDepth = 200;

// Expand `#include "file"` (and `#include <file>`, searched in include_dirs
// only) recursively in `root_text`. The root is shown as `root_name` in
// errors and is source string 0; its relative includes resolve against
// root_dir, then include_dirs. Absolute include paths are allowed.
// Throws ms::Error (bad_input) for cycles, missing includes, a #version in an
// included file, malformed #include lines, (with opts.roots) an include
// outside the roots, a shader over opts.limits and a live #error, located
// at file:line. The confinement error names the path and is raised before
// the file is opened: none of its content is ever shown.
// A user's `#line L` in an included file renumbers that file's lines from L.
ShaderSource preprocess(std::string_view root_text, const std::string& root_name,
                        const std::filesystem::path& root_dir, const PreprocessOptions& opts);

}  // namespace ms
