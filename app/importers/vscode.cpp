#include "importers/vscode.h"
#include "importers/vscode_files.h"

#include <algorithm>
#include <regex>

#include "core/error.h"
#include "io/cube_faces.h"
#include "io/input_file.h"
#include "io/path_roots.h"
#include "preprocess/directive.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {


Sampler sampler_of(const VsChannel& c, const VsFile& f, int n, Sampler s, std::vector<std::string>& warnings) {
  const std::string key = "#iChannel" + std::to_string(n);
  if (c.wrap) s.wrap = *c.wrap == "Clamp" ? TexWrap::clamp : *c.wrap == "Repeat" ? TexWrap::repeat : TexWrap::mirror;
  if (!c.min && !c.mag) return s;
  const std::string mn = c.min.value_or("Linear"), mg = c.mag.value_or("Linear");
  if (mn.find("MipMap") != std::string::npos) {
    s.filter = TexFilter::mipmap;
    if (mn != "LinearMipMapLinear" || mg != "Linear")
      warnings.push_back(f.where + ":" + std::to_string(c.min_line) + ": " + key + "::MinFilter \"" + mn +
                         "\" with MagFilter \"" + mg + "\" is drawn as LinearMipMapLinear and Linear, marchstudio's mipmap filter");
  } else {
    s.filter = mg == "Nearest" ? TexFilter::nearest : TexFilter::linear;
    if (mn != mg)
      warnings.push_back(f.where + ":" + std::to_string(c.min_line ? c.min_line : c.mag_line) + ": " + key +
                         ": MinFilter \"" + mn + "\" and MagFilter \"" + mg + "\" differ; both are drawn \"" + mg + "\"");
  }
  return s;
}

// The extension's keyboard functions on Shadertoy's keyboard texture
// (row 0 down, 1 pressed this frame, 2 toggled); macros, so that each pass
// reads its own channel through its `#define iKeyboard iChannelN`.
// void main() files: gl_FragColor is a global until each pass's end, where
// a mainImage calls the user's main, renamed msVsMain in its text (the
// wrapper has its own main()), and returns it. gl_FragCoord is already the
// wrapper's whole-image coordinate.
std::string main_prelude() { return "vec4 msVsFragColor;\n#define gl_FragColor msVsFragColor\n"; }
std::string main_suffix(bool uses_main) {
  std::string s = "\n#undef gl_FragColor\n";
  if (uses_main) s += "void mainImage(out vec4 c, in vec2 f) { msVsFragColor = vec4(0.0); msVsMain(); c = msVsFragColor; }\n";
  return s;
}

std::string keyboard_prelude() {
  std::string s =
      "#define isKeyDown(key) (texelFetch(iKeyboard, ivec2(int(key), 0), 0).r > 0.0)\n"
      "#define isKeyPressed(key) (texelFetch(iKeyboard, ivec2(int(key), 1), 0).r > 0.0)\n"
      "#define isKeyToggled(key) (texelFetch(iKeyboard, ivec2(int(key), 2), 0).r > 0.0)\n"
      "#define isKeyReleased(key) (int(key) < 0)  // Shadertoy's texture has no released row: false\n"
      "const int Key_Backspace = 8, Key_Tab = 9, Key_Enter = 13, Key_Shift = 16, Key_Ctrl = 17, Key_Alt = 18,\n"
      "  Key_Pause = 19, Key_Caps = 20, Key_Escape = 27, Key_Space = 32, Key_PageUp = 33, Key_PageDown = 34,\n"
      "  Key_End = 35, Key_Home = 36, Key_LeftArrow = 37, Key_UpArrow = 38, Key_RightArrow = 39,\n"
      "  Key_DownArrow = 40, Key_Insert = 45, Key_Delete = 46";
  for (int d = 0; d < 10; ++d) s += ", Key_" + std::to_string(d) + " = " + std::to_string(48 + d);
  for (char c = 'A'; c <= 'Z'; ++c) s += std::string(", Key_") + c + " = " + std::to_string(static_cast<int>(c));
  for (int d = 0; d < 10; ++d) s += ", Key_Numpad" + std::to_string(d) + " = " + std::to_string(96 + d);
  for (int d = 1; d <= 12; ++d) s += ", Key_F" + std::to_string(d) + " = " + std::to_string(111 + d);
  s += ",\n  Key_NumpadMultiply = 106, Key_NumpadAdd = 107, Key_NumpadSubtract = 109, Key_NumpadPeriod = 110,\n"
       "  Key_NumpadDivide = 111, Key_NumLock = 144, Key_ScrollLock = 145, Key_SemiColon = 186, Key_Equal = 187,\n"
       "  Key_Comma = 188, Key_Dash = 189, Key_Period = 190, Key_ForwardSlash = 191, Key_GraveAccent = 192,\n"
       "  Key_OpenBracket = 219, Key_BackSlash = 220, Key_CloseBraket = 221, Key_SingleQuote = 222;\n";
  return s;
}

// Channel `n` of file `f` (pass `i` of `files`) as the pass reads it: a
// buffer (a shader file, or the file itself), a cubemap, an image or audio.
void bind_channel(const std::vector<VsFile>& files, size_t i, size_t n, ProjectInput& in,
                  std::vector<std::string>& warnings) {
  const VsFile& f = files[i];
  const VsChannel& c = f.ch[n];
  const std::string key = "#iChannel" + std::to_string(n);
  if (!c.line) {
    if (c.type || c.min || c.mag || c.wrap)
      warnings.push_back(f.where + ": " + key + " has settings but no " + key + " line binds it; they do nothing");
    return;
  }
  const bool cube = c.type && *c.type == "CubeMap";
  if (c.self || c.kind == VsKind::shader) {
    if (cube) fail_input(key + "::Type \"CubeMap\": a shader's buffer is 2D", f.where, c.type_line, key + "::Type", kVscodeDoc);
    in.kind = InputKind::buffer;
    in.buffer = static_cast<int>(i);
    if (!c.self) {
      const auto other = std::find_if(files.begin(), files.end(), [&](const VsFile& o) { return o.path == c.path; });
      in.buffer = other == files.end() ? -1 : static_cast<int>(other - files.begin());
    }
    in.sampler = sampler_of(c, f, static_cast<int>(n), {TexFilter::linear, TexWrap::clamp, false, false}, warnings);
    return;
  }
  if (c.kind == VsKind::video)
    fail_input(key + ": '" + display_path(c.path) + "' is a video, which the extension does not play", f.where, c.line, key,
               "an image, an audio file or a .glsl buffer");
  in.src = c.path.string();
  // The extension's textures: linear, repeat, flipped upright (three.js's flipY).
  in.sampler = sampler_of(c, f, static_cast<int>(n), {TexFilter::linear, TexWrap::repeat, true, false}, warnings);
  if (cube) {
    if (c.path.string().find("{}") == std::string::npos)
      fail_input(key + "::Type \"CubeMap\": the path needs the '{}' wildcard for its six faces", f.where, c.line, key,
                 "e.g. \"file://sky_{}.png\" for sky_px.png .. sky_nz.png");
    in.kind = InputKind::cubemap;  // the six faces are found from the wildcard where cubemaps are loaded
    in.sampler.vflip = false;      // cube faces are not flipped (three.js CubeTexture, GL's face table)
    return;
  }
  const std::string problem = input_file_problem(c.path);
  if (!problem.empty()) fail_input(key + ": '" + display_path(c.path) + "' " + problem, f.where, c.line, key, kVscodeDoc);
  in.kind = c.kind == VsKind::audio ? InputKind::music : InputKind::texture;
  in.file = c.path;
  if (in.kind == InputKind::music) in.sampler = {TexFilter::linear, TexWrap::clamp, false, false};
}

// #iKeyboard: the first free channel, its line made the #define that names
// it. False when the file has no such line.
bool bind_keyboard(VsFile& f, ProjectPass& ps) {
  if (!f.keyboard_line) return false;
  size_t free = 0;
  while (free < 4 && ps.inputs[free].kind != InputKind::none) ++free;
  if (free == 4)
    fail_input("#iKeyboard: all four channels are bound; the keyboard needs one", f.where, f.keyboard_line, "#iKeyboard",
               "marchstudio binds the keyboard to a free iChannel; free one");
  ps.inputs[free].kind = InputKind::keyboard;
  std::vector<std::string> lines = line_strings(f.code);
  lines[static_cast<size_t>(f.keyboard_line) - 1] = "#define iKeyboard iChannel" + std::to_string(free);
  f.code.clear();
  for (size_t k = 0; k < lines.size(); ++k) f.code += lines[k] + (k + 1 < lines.size() ? "\n" : "");
  return true;
}

// The file that reads the main file (itself included), and the line that
// does: the main file is then a buffer too, shown by a display pass.
const VsFile* reader_of_main(const std::vector<VsFile>& files, int& line) {
  const VsFile& main = files.back();
  for (const VsFile& f : files)
    for (const VsChannel& c : f.ch)
      if (c.line && ((c.self && &f == &main) || (!c.self && c.path == main.path))) {
        line = c.line;
        return &f;
      }
  return nullptr;
}

// The Image pass that shows the main file's buffer (the last of `buffers`).
ProjectPass display_pass(const VsFile& main, int buffers, bool any_main) {
  ProjectPass show;
  show.kind = PassKind::image;
  show.name = "Image";
  show.where = main.where + " (display)";
  show.code = "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n";
  if (any_main) show.code += main_suffix(false);
  show.inputs[0].kind = InputKind::buffer;
  show.inputs[0].buffer = buffers - 1;
  show.inputs[0].sampler = {TexFilter::nearest, TexWrap::clamp, false, false};
  return show;
}

}  // namespace

bool looks_like_vscode(std::string_view source) {
  for (const std::string& line : line_strings(strip_comments(source)))
    if (!directive_name(line).empty()) return true;
  return false;
}

ShaderProject load_vscode(const std::string& text, const fs::path& file, const std::vector<fs::path>& roots) {
  std::vector<VsFile> files = read_vscode_files(text, file, roots);  // the main file last
  const VsFile& main = files.back();
  int reads_main_line = 0;
  const VsFile* reads_main = reader_of_main(files, reads_main_line);
  const bool any_main = std::any_of(files.begin(), files.end(), [](const VsFile& f) { return f.uses_main; });
  const size_t buffers = files.size() - 1 + (reads_main ? 1 : 0);
  if (buffers > 4) {
    const VsFile& fifth = reads_main && files.size() <= 5 ? main : files[4];
    const int line = &fifth == &main ? reads_main_line : fifth.from_line;
    fail_input(std::to_string(buffers) + " buffers: marchstudio runs at most 4", &fifth == &main ? reads_main->where : fifth.from_where,
               line, "#iChannel", "Shadertoy's Buffer A..D; merge two buffer files");
  }
  ShaderProject p;
  p.origin = file;
  p.name = file.stem().string();
  bool keyboard = false;
  for (size_t i = 0; i < files.size(); ++i) {
    VsFile& f = files[i];
    const bool is_buffer = i + 1 < files.size() || reads_main;
    ProjectPass ps;
    ps.kind = is_buffer ? PassKind::buffer : PassKind::image;
    ps.output = is_buffer ? static_cast<int>(i) : -1;
    ps.name = is_buffer ? "Buffer " + buffer_letter(ps.output) : "Image";
    ps.file = f.path;
    ps.where = f.where;
    for (size_t n = 0; n < 4; ++n) bind_channel(files, i, n, ps.inputs[n], p.warnings);
    keyboard = bind_keyboard(f, ps) || keyboard;
    ps.code = f.uses_main ? std::regex_replace(f.code, std::regex(R"(\bmain\b)"), "msVsMain") : f.code;
    if (any_main) ps.code += main_suffix(f.uses_main);
    p.passes.push_back(std::move(ps));
  }
  if (reads_main) p.passes.push_back(display_pass(main, static_cast<int>(files.size()), any_main));
  if (keyboard || any_main) {
    p.common = (any_main ? main_prelude() : std::string()) + (keyboard ? keyboard_prelude() : std::string());
    p.common_where = main.where + (keyboard ? " (#iKeyboard functions)" : " (main() entry point)");
  }
  check_project(p, main.where);
  return p;
}

}  // namespace ms
