#include "cli/input_flags.h"

#include <cmath>
#include <cstdlib>
#include <regex>
#include <string_view>

#include "cli/flag_checks.h"
#include "core/error.h"
#include "pipeline/shader_dir.h"
#include "core/suggest.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// MissingMedia's values, in its order.
const std::vector<std::string> kMissingMediaNames = {"error", "noise", "black"};

}  // namespace

DisabledEffects parse_disabled(const std::vector<std::string>& names) {
  DisabledEffects d;
  for (const std::string& n : names) {
    if (n == "shadows") d.shadows = true;
    else if (n == "reflections") d.reflections = true;
    else if (n == "ao") d.ao = true;
    else if (n == "checker-filter") d.checker_filter = true;
    else if (n == "bloom") d.bloom = true;
    else fail_not_one_of(n, kEffectNames, "--disable");
  }
  return d;
}

ImageSize parse_size_flag(const std::string& text, const std::string& flag) {
  static const std::regex re(R"(^\s*(\d{1,9})\s*[xX]\s*(\d{1,9})\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    fail_input("invalid size '" + text + "'", {}, 0, flag, "expected WxH, e.g. 1280x720");
  ImageSize out{std::stoi(m[1]), std::stoi(m[2])};
  if (out.width < 1 || out.height < 1) fail_input("image size " + text + " must be at least 1x1", {}, 0, flag);
  return out;
}

std::vector<std::pair<std::string, std::string>> parse_defines(const std::vector<std::string>& flags) {
  static const std::regex ident(R"(^[A-Za-z_][A-Za-z0-9_]*$)");
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& f : flags) {
    const size_t eq = f.find('=');
    std::string name = f.substr(0, eq), value = eq == std::string::npos ? "1" : f.substr(eq + 1);
    if (!std::regex_match(name, ident))
      fail_input("'" + name + "' is not a GLSL identifier", {}, 0, "-D", "use -D NAME or -D NAME=VALUE");
    if (const std::string problem = define_value_problem(value); !problem.empty())
      fail_input("the value of '" + name + "' " + problem, {}, 0, "-D", "one line, without a trailing '\\'");
    out.emplace_back(std::move(name), std::move(value));
  }
  return out;
}

std::vector<fs::path> parse_allow_include(const std::vector<std::string>& flags) {
  std::vector<fs::path> dirs;
  for (const std::string& f : flags) {
    std::error_code ec;
    if (f.empty() || !fs::is_directory(f, ec))
      fail_input("'" + f + "' is not a directory", {}, 0, "--allow-include",
                 "--allow-include DIR lets #include read files under DIR");
    dirs.push_back(fs::canonical(f, ec));
  }
  return dirs;
}

MissingMedia parse_missing_media(const std::string& text) {
  for (size_t i = 0; i < kMissingMediaNames.size(); ++i)
    if (text == kMissingMediaNames[i]) return static_cast<MissingMedia>(i);
  fail_not_one_of(text, kMissingMediaNames, "--missing-media");
}

NamedTexture parse_texture_flag(const std::string& text, int unnamed_before) {
  static const std::regex named(R"(^([A-Za-z_][A-Za-z0-9_]*)=(.+)$)");
  std::smatch m;
  NamedTexture t;
  if (std::regex_match(text, m, named)) {
    t.name = m[1];
    t.file = m[2].str();
  } else {
    t.name = "u_tex" + std::to_string(unnamed_before);  // glslViewer's order for positional images
    t.file = text;
  }
  if (t.file.empty()) fail_input("invalid --texture '" + text + "'", {}, 0, "--texture", "FILE or NAME=FILE");
  std::error_code ec;
  t.file = fs::absolute(t.file, ec);
  return t;
}

void add_shadertoy_flags(CLI::App* cmd, ShadertoyOptions& f) {
  cmd->add_option("--media-dir", f.media_dir,
                  "Where a Shadertoy shader's media (/media/a/<name>) are found, by file name (default: the shader's "
                  "directory, or the scene's [shadertoy] media_dir)")
      ->check(not_empty());
  cmd->add_option_function<std::string>(
         "--missing-media", [&f](const std::string& v) { f.missing_media = parse_missing_media(v); },
         "For a texture not in the media directory: error (default), noise or black stand-ins, with a warning")
      ->check(one_of(kMissingMediaNames));
  cmd->add_option_function<std::string>(
         "--mouse", [&f](const std::string& v) { f.mouse = parse_mouse_flag(v); },
         "iMouse of a Shadertoy shader: X,Y,Z,W in pixels, or u_mouse of a glslViewer shader: X,Y (default: the scene's, "
         "else 0,0,0,0)");
  cmd->add_option_function<std::vector<std::string>>(
         "--texture",
         [&f](const std::vector<std::string>& v) {
           int unnamed = 0;  // FILE alone: glslViewer's positional order, u_tex0, u_tex1, ..
           for (const std::string& one : v) {
             f.textures.push_back(parse_texture_flag(one, unnamed));
             const std::string& name = f.textures.back().name;
             if (one.compare(0, name.size() + 1, name + "=") != 0) ++unnamed;
           }
         },
         "A glslViewer shader's texture: FILE binds u_tex0, u_tex1, .. in order; NAME=FILE binds the sampler2D NAME "
         "(repeatable)")
      ->allow_extra_args(false)
      ->type_size(1)
      ->expected(1, CLI::detail::expected_max_vector_size);
}

std::vector<float> parse_mouse_flag(const std::string& text) {
  std::vector<float> v;
  size_t at = 0;
  const char* hint = "X,Y (glslViewer's u_mouse) or X,Y,Z,W (Shadertoy's iMouse), in pixels";
  while (at <= text.size() && v.size() < 5) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string part = text.substr(at, comma - at);
    char* end = nullptr;
    const double d = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(d) || std::abs(d) > 1e9)
      fail_input("invalid --mouse '" + text + "'", {}, 0, "--mouse", hint);
    v.push_back(static_cast<float>(d));
    at = comma + 1;
  }
  if (v.size() == 2) v.resize(4, 0.0f);  // a position alone: no click
  if (v.size() != 4) fail_input("invalid --mouse '" + text + "'", {}, 0, "--mouse", hint);
  return v;
}

}  // namespace ms
