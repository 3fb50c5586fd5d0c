// glslViewer's fragment shaders (patriciogonzalezvivo/glslViewer) as a
// ShaderProject: `void main()` writing gl_FragColor, glslViewer's u_*
// uniforms, and the same file compiled once per `#ifdef BUFFER_N` (a
// buffer) and `#ifdef DOUBLE_BUFFER_N` (a ping-pong buffer reading its own
// previous frame), mapped onto Shadertoy's Buffer A..D in glslViewer's run
// order: BUFFER_0.., then DOUBLE_BUFFER_0.., then the main pass (into one
// more buffer when an #ifdef POSTPROCESSING pass reads it as u_scene, last).
// What marchstudio does not run (3D scenes, cubemaps, pyramids, floods,
// sized buffers) is refused at its line. docs/glslviewer.md.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "shader/assemble.h"
#include "preprocess/preprocess.h"
#include "scene/project.h"

namespace ms {

// True when `source` (comments ignored) defines main() and no mainImage,
// and writes gl_FragColor or declares a glslViewer u_* uniform.
bool looks_like_glslviewer(std::string_view source);

// The passes of a glslViewer file read as `text` from `file` (absolute).
// Throws bad_input naming file:line and the name for what is refused.
ShaderProject load_glslviewer(const std::string& text, const std::filesystem::path& file);

// Pass `index` of a glslViewer project: the file with the pass's define
// (BUFFER_0, DOUBLE_BUFFER_0 or none), GLSLVIEWER and PLATFORM_LINUX, and
// GLSL 1.x spelled for #version 450 core (gl_FragColor, texture2D,
// varying; v_texcoord etc. as glslViewer's billboard vertex shader gives
// them). Errors name the file's own lines.
ShaderSource assemble_glslviewer_pass(const ShaderProject& p, size_t index, const AssembleOptions& opts,
                                      const std::vector<std::filesystem::path>& roots);

// Binds `textures` (--texture, in order) to the samplers the project
// declares by name; a name nothing declares is a warning. On a project
// that is not glslViewer's, any texture is an error naming --texture.
void bind_glslviewer_textures(ShaderProject& p, const std::vector<NamedTexture>& textures,
                              std::vector<std::string>& warnings);

}  // namespace ms
