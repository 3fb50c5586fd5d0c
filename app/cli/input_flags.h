// The flags that say what to load, parsed once here into the typed values
// pipeline/input.h takes: sizes, defines, include directories, Shadertoy's
// media, mouse and textures. Every error names its flag.
//
//   ImageSize s = parse_size_flag("1280x720");             // throws bad_input naming --size
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/frame_job.h"
#include "pipeline/input.h"
#include "pipeline/shader_dir.h"
#include "shader/assemble.h"

namespace CLI {
class App;
}

namespace ms {

// --media-dir, --missing-media, --mouse and --texture on a subcommand (--fps is its own).
void add_shadertoy_flags(CLI::App* cmd, ShadertoyOptions& f);
// "X,Y,Z,W" as iMouse, or "X,Y" (glslViewer's u_mouse; Z and W 0). Throws
// bad_input naming --mouse.
std::vector<float> parse_mouse_flag(const std::string& text);
// "error", "noise" or "black" (--missing-media). Throws bad_input naming
// the flag, with a did-you-mean.
MissingMedia parse_missing_media(const std::string& text);
// One --texture: "NAME=FILE" binds NAME, "FILE" binds u_tex<unnamed_before>;
// the file made absolute (it is checked when applied).
NamedTexture parse_texture_flag(const std::string& text, int unnamed_before);

// --disable's names (each one of kEffectNames, cli/flag_checks.h) as the
// effects they switch off. Throws bad_input naming --disable, with a
// did-you-mean, for another name.
DisabledEffects parse_disabled(const std::vector<std::string>& names);

// A "WxH" flag value (render/bench --size, view --size/--shot-size); each
// side at least 1. Whether the GL can make it is checked later, with a context.
ImageSize parse_size_flag(const std::string& text, const std::string& flag = "--size");

// "NAME" or "NAME=VALUE" flags as (name, value) #defines; NAME must be a
// GLSL identifier, VALUE one line. Throws bad_input naming -D.
std::vector<std::pair<std::string, std::string>> parse_defines(const std::vector<std::string>& flags);

// --allow-include DIR flags: each an existing directory, made canonical
// (AssembleOptions::allow_include). Throws bad_input naming the flag.
std::vector<std::filesystem::path> parse_allow_include(const std::vector<std::string>& flags);

}  // namespace ms
