#include "shader/shadertoy.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <system_error>

#include "core/error.h"

namespace ms {

namespace fs = std::filesystem;

namespace {

// Comments replaced by spaces, newlines kept, so offsets still give lines.
std::string strip_comments(std::string_view s) {
  std::string out(s);
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i] != '/' || i + 1 >= out.size()) continue;
    if (out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      for (i += 2; i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/'); ++i)
        if (out[i] != '\n') out[i] = ' ';
      if (i < out.size()) out[i] = out[i + 1] = ' ';
      ++i;
    }
  }
  return out;
}

const std::regex& main_def() {
  static const std::regex re(R"(\bvoid\s+main\s*\()");
  return re;
}

const std::regex& main_image_def() {
  static const std::regex re(R"(\bvoid\s+mainImage\s*\()");
  return re;
}

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
         "  outColor = vec4(c.rgb, 1.0);\n"
         "}\n";
}

}  // namespace

bool looks_like_shadertoy(std::string_view source) {
  std::string s = strip_comments(source);
  return std::regex_search(s, main_image_def()) && !std::regex_search(s, main_def());
}

ShaderSource assemble_shadertoy(const fs::path& glsl_file, const AssembleOptions& opts) {
  std::error_code ec;
  fs::path abs = fs::absolute(glsl_file, ec).lexically_normal();
  std::ifstream in(abs, std::ios::binary);
  if (ec || !fs::is_regular_file(abs, ec) || !in)
    fail_input("cannot read the Shadertoy shader", display_path(glsl_file));
  std::string user((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

  std::string code = strip_comments(user);
  std::smatch m;
  if (std::regex_search(code, m, main_def())) {
    int line = 1 + static_cast<int>(std::count(code.begin(), code.begin() + m.position(0), '\n'));
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
  ShaderSource src = preprocess(root, display_path(abs) + " (shadertoy wrapper)", abs.parent_path(),
                                PreprocessOptions{{opts.shader_dir}});
  // mainImage may come from a file the shader includes, so look after expansion.
  if (!std::regex_search(strip_comments(src.text), main_image_def()))
    fail_input("no mainImage() found in the Shadertoy shader", display_path(abs), 0, {},
               "define void mainImage(out vec4 fragColor, in vec2 fragCoord)");
  return src;
}

}  // namespace ms
