#include "shader/shadertoy.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include "io/input_file.h"
#include "core/error.h"
#include "shader/glsl_scan.h"

namespace ms {

namespace fs = std::filesystem;

namespace {

// The part of the wrapper before the user's file. Shadertoy's uniform set,
// spelled as on shadertoy.com so shaders paste in unchanged.
const char* wrapper_head() {
  return "#version 450 core\n"
         "uniform vec3      iResolution;           // viewport, pixels (z = 1)\n"
         "uniform float     iTime;                 // seconds\n"
         "uniform float     iTimeDelta;\n"
         "uniform float     iFrameRate;\n"
         "uniform int       iFrame;\n"
         "uniform vec4      iMouse;\n"
         "uniform vec4      iDate;                 // year, month, day, seconds\n"
         "uniform float     iSampleRate;\n"
         "uniform float     iChannelTime[4];\n"
         "uniform vec3      iChannelResolution[4];\n"
         "uniform sampler2D iChannel0;\n"
         "uniform sampler2D iChannel1;\n"
         "uniform sampler2D iChannel2;\n"
         "uniform sampler2D iChannel3;\n"
         "uniform vec2      uJitter;               // marchstudio: sub-pixel sample position\n"
         "layout(location = 0) out vec4 outColor;\n";
}

const char* wrapper_tail() {
  return "void main() {\n"
         "  vec4 c = vec4(0.0, 0.0, 0.0, 1.0);\n"
         "  mainImage(c, floor(gl_FragCoord.xy) + uJitter);\n"
         "  // marchstudio: a NaN/Inf sample is zeroed but flagged by a negative alpha\n"
         "  // sum (spp <= 1024); the post pass turns the pixel NaN for the host's guard.\n"
         "  bool bad = any(isnan(c.rgb)) || any(isinf(c.rgb));\n"
         "  outColor = bad ? vec4(0.0, 0.0, 0.0, -4096.0) : vec4(c.rgb, 1.0);\n"
         "}\n";
}

}  // namespace

bool looks_like_shadertoy(std::string_view source) {
  std::string s = strip_comments(source);
  return find_definition(s, "mainImage") != std::string_view::npos &&
         find_definition(s, "main") == std::string_view::npos;
}

ShaderSource assemble_shadertoy(const fs::path& glsl_file, const AssembleOptions& opts, const fs::path& scene_file) {
  std::error_code ec;
  fs::path abs = fs::absolute(glsl_file, ec).lexically_normal();
  PreprocessOptions popts;
  popts.include_dirs = {opts.shader_dir};
  // A bare shader was named on the command line: its real directory is the
  // root, even through a symlink. A wrapped one must lie in its scene's.
  popts.roots = include_roots(scene_file.empty() ? fs::weakly_canonical(abs, ec) : scene_file, opts);
  if (!within_roots(abs, popts.roots))
    fail_input("the Shadertoy shader '" + display_path(abs) + "' is outside the directories includes may read",
               display_path(scene_file.empty() ? glsl_file : scene_file), 0, scene_file.empty() ? "" : "scene.shadertoy",
               "allowed: " + describe_roots(popts.roots) + "; widen with --allow-include DIR");
  // Regular files only: opening a FIFO would block.
  const std::string user = read_input_file(abs, "Shadertoy shader", scene_file.empty() ? "" : "scene.shadertoy");

  std::string code = strip_comments(user);
  if (const size_t at = find_definition(code, "main"); at != std::string_view::npos) {
    int line = 1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    fail_input("a Shadertoy shader must not define main()", display_path(abs), line, {},
               "define void mainImage(out vec4 fragColor, in vec2 fragCoord) instead");
  }
  std::string path = abs.generic_string();
  if (path.find_first_of("\"\n\r") != std::string::npos)
    fail_input("the shader path contains a quote or newline", display_path(abs));

  std::string root = wrapper_head();
  for (const auto& [name, value] : opts.defines) root += "#define " + name + " " + value + "\n";
  root += "#include \"" + path + "\"\n";
  root += wrapper_tail();
  ShaderSource src = preprocess(root, display_path(abs) + " (shadertoy wrapper)", abs.parent_path(), popts);
  // mainImage may come from a file the shader includes, so look after expansion.
  if (find_definition(strip_comments(src.text), "mainImage") == std::string_view::npos) {
    // A scene's map file handed over by mistake: point at its scene.
    fs::path toml = abs;
    toml.replace_extension(".toml");
    std::string hint = "define void mainImage(out vec4 fragColor, in vec2 fragCoord)";
    if (find_definition(code, "map", "vec2") != std::string_view::npos)
      hint = fs::is_regular_file(toml, ec) ? "it defines map(): render its scene, " + display_path(toml)
                                           : "it defines map(): a map file is rendered through a scene .toml whose "
                                             "[scene] map names it (docs/scene-format.md)";
    fail_input("no mainImage() found in the Shadertoy shader", display_path(abs), 0, {}, hint);
  }
  return src;
}

}  // namespace ms
