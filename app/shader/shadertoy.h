// Runs a Shadertoy single-pass shader (mainImage(out vec4, in vec2)) as a
// #version 450 core fragment shader: a generated wrapper declares Shadertoy's
// uniforms, includes the user's file and calls mainImage from main().
#pragma once
#include <filesystem>
#include <string_view>

#include "shader/assemble.h"
#include "shader/preprocess.h"

namespace ms {

// The wrapper is source string 0 ("<file> (shadertoy wrapper)"); the user's
// file is included by absolute path, so its errors map to its own lines, and
// its own #includes resolve next to it, then in opts.shader_dir.
// Uniforms, set by the host: iResolution, iTime, iTimeDelta, iFrameRate,
// iFrame, iMouse, iDate, iSampleRate, iChannelTime[4], iChannelResolution[4],
// iChannel0..3 (sampler2D), and uJitter (sub-pixel sample position, 0.5,0.5
// = pixel centre). Throws ms::Error when the file is missing or defines main().
// Includes may read scene_file's directory (the .toml that wraps the shader;
// empty: the shader's own, symlinks resolved), opts.shader_dir and opts.allow_include, and the
// shader itself must lie there.
ShaderSource assemble_shadertoy(const std::filesystem::path& glsl_file, const AssembleOptions& opts,
                                const std::filesystem::path& scene_file = {});

// True when `source` (comments ignored) defines mainImage and no main().
bool looks_like_shadertoy(std::string_view source);

}  // namespace ms
