// Files for the VS Code "Shader Toy" extension (stevensona.shader-toy) as a
// ShaderProject: a mainImage shader whose `#iChannelN "file://..."` lines
// name its inputs. A .glsl (any file that is not an image or audio) is a
// buffer pass, itself read the same way, so buffers can name buffers;
// "self" is the pass's own previous frame; `::Type`, `::MinFilter`,
// `::MagFilter` and `::WrapMode` set the channel's kind and sampler;
// `#iKeyboard` binds Shadertoy's keyboard texture and defines the
// extension's isKeyDown() etc.; `#iUniform` becomes an annotated uniform
// (shader/scene_params.h: a slider in the viewer, --uniform on render).
// Each directive line is replaced by one line (blank, or its GLSL), so
// errors name the file's own lines. Passes take Buffer A..D in the order
// the extension runs them: a file after everything it reads, the main file
// last. docs/vscode.md.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/project.h"

namespace ms {

// True when a line of `source` (outside comments) starts with one of the
// extension's directives: #iChannelN, #iKeyboard, #iUniform,
// #iFirstPersonControls, #StrictCompatibility, #iVertex.
bool looks_like_vscode(std::string_view source);

// The passes of the extension's file read as `text` from `file` (absolute).
// Every file it names must lie inside `roots` (preprocess/confine.h). Throws
// bad_input naming file:line and the directive for what is refused.
ShaderProject load_vscode(const std::string& text, const std::filesystem::path& file,
                          const std::vector<std::filesystem::path>& roots);

// The GLSL line standing for `#iUniform <args>` (args: what follows the
// directive, e.g. "float k = 1.0 in { 0.0, 5.0 } step 0.1"): an annotated
// uniform declaration that parse_scene_params() reads. Throws bad_input
// naming `where`:`line` and #iUniform for what it cannot map.
std::string vscode_uniform_line(const std::string& args, const std::string& where, int line);

}  // namespace ms
