// Shadertoy shaders as #version 450 core fragment shaders. A file (a .glsl
// with mainImage, or Shadertoy's JSON) becomes a ShaderProject
// (scene/project.h); each of its passes is assembled with a generated
// wrapper that declares Shadertoy's uniforms and typed channels, defines
// HW_PERFORMANCE, puts the Common source first, renames desktop-only
// keywords (importers/es_compat.h) and calls mainImage from main().
//
//   ShaderProject p = load_shadertoy_file("x.json", opts);
//   for (size_t i = 0; i < p.passes.size(); ++i) passes.push_back(assemble_shadertoy_pass(p, i, opts));
#pragma once
#include <filesystem>
#include <string_view>

#include "shader/assemble.h"
#include "preprocess/preprocess.h"
#include "scene/project.h"

namespace ms {

// Reads `file` (a regular file inside the include roots: `scene_file`'s
// directory when it wraps the shader, else the file's own, plus
// opts.shader_dir and opts.allow_include). JSON by its .json extension or
// its first byte; otherwise GLSL, one Image pass. Throws ms::Error.
ShaderProject load_shadertoy_file(const std::filesystem::path& file, const AssembleOptions& opts,
                                  const std::filesystem::path& scene_file = {});

// Pass `index` of `p`. Source string 0 is the wrapper; the Common source
// and the pass's code are files of their own, so errors name "x.json
// (Buffer A):12" or the pass file's line. Uniforms, set by the host:
// iResolution, iTime, iTimeDelta, iFrameRate, iFrame, iMouse, iDate,
// iSampleRate, iChannelTime[4], iChannelResolution[4], iChannel0..3, and
// uJitter (the Image pass's sub-pixel sample position). The Image pass
// writes (rgb, 1), a non-finite channel as a float-to-unorm write makes it
// (NaN 0, +Inf 1, -Inf 0) and flagged in alpha; buffer passes write the
// whole vec4 as it is. Throws ms::Error for main() defined, no mainImage,
// or anything preprocess() refuses.
ShaderSource assemble_shadertoy_pass(const ShaderProject& p, size_t index, const AssembleOptions& opts,
                                     const std::filesystem::path& scene_file = {});

// load_shadertoy_file() then its Image pass: a single-pass shader.
ShaderSource assemble_shadertoy(const std::filesystem::path& glsl_file, const AssembleOptions& opts,
                                const std::filesystem::path& scene_file = {});

// True when `source` (comments ignored) defines mainImage and no main().
bool looks_like_shadertoy(std::string_view source);

// The include roots of a project's passes (see load_shadertoy_file).
std::vector<std::filesystem::path> project_roots(const ShaderProject& p, const AssembleOptions& opts,
                                                 const std::filesystem::path& scene_file);

}  // namespace ms
