#include "importers/vscode.h"

#include <algorithm>
#include <regex>
#include <array>
#include <cctype>
#include <map>
#include <optional>
#include <system_error>

#include "core/error.h"
#include "io/image_io.h"
#include "preprocess/directive.h"
#include "io/cube_faces.h"
#include "io/input_file.h"
#include "preprocess/confine.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

constexpr const char* kDoc = "docs/vscode.md lists what runs";
constexpr std::size_t kMaxBuffers = 4;  // Shadertoy's Buffer A..D


// The directive a (comment-free) line starts with: "iChannel2", "iKeyboard"...;
// empty when it starts with none of the extension's.
std::string directive_name(const std::string& line) {
  size_t i = line.find_first_not_of(" \t\r");
  if (i == std::string::npos || line[i] != '#') return {};
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos) return {};
  size_t j = i;
  while (j < line.size() && (std::isalnum(static_cast<unsigned char>(line[j])) || line[j] == '_')) ++j;
  const std::string name = line.substr(i, j - i);
  if (name.size() > 8 && name.compare(0, 8, "iChannel") == 0 &&
      std::all_of(name.begin() + 8, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return name;
  for (const char* d : {"iKeyboard", "iUniform", "iFirstPersonControls", "StrictCompatibility", "iVertex"})
    if (name == d) return name;
  return {};
}

// What follows the directive on the raw line, its `//` comment dropped
// (outside quotes: "file://x" keeps its slashes).
std::string directive_args(const std::string& raw, const std::string& name) {
  std::string s = raw.substr(raw.find(name) + name.size());
  bool quoted = false;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '"') quoted = !quoted;
    if (!quoted && s.compare(i, 2, "//") == 0) return s.substr(0, i);
    if (!quoted && s.compare(i, 2, "/*") == 0) return s.substr(0, i);
  }
  return s;
}

std::string lower_ext(const fs::path& p) {
  std::string e = p.extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The extension sorts an input by its MIME type: image, audio, or (any
// other, text included) a shader.
enum class FileKind { shader, image, audio, video };
FileKind kind_of(const fs::path& p) {
  const std::string e = lower_ext(p);
  if (is_image_name(p)) return FileKind::image;
  for (const char* x : {".mp3", ".wav", ".ogg", ".oga", ".flac", ".m4a", ".aac", ".opus"})
    if (e == x) return FileKind::audio;
  for (const char* x : {".mp4", ".webm", ".ogv", ".mov", ".mkv", ".avi"})
    if (e == x) return FileKind::video;
  return FileKind::shader;
}

struct Channel {
  int line = 0;                 // of its #iChannelN "..." line; 0: none
  bool self = false;
  fs::path path;                // absolute, normalised
  FileKind kind = FileKind::shader;
  std::optional<std::string> min, mag, wrap, type;
  int type_line = 0, min_line = 0, mag_line = 0, wrap_line = 0;
};

struct File {
  fs::path path;
  std::string where;
  std::string code;             // directives replaced by their one-line GLSL (or blank)
  std::array<Channel, 4> ch{};
  int keyboard_line = 0;
  bool uses_main = false;       // void main() with gl_FragColor, the extension's other entry point
  std::string from_where;       // the directive that first named it
  int from_line = 0;
};

struct Loader {
  const std::vector<fs::path>& roots;
  std::vector<File> order;      // post-order: a file after the files it reads
  std::vector<fs::path> visiting;

  [[noreturn]] void fail(const std::string& what, const std::string& where, int line, const std::string& key,
                         const std::string& hint = kDoc) {
    fail_input(what, where, line, key, hint);
  }

  fs::path resolve(const std::string& given, const File& f, int line, const std::string& key) {
    fs::path p(given);
    if (p.is_relative()) p = f.path.parent_path() / p;
    std::error_code ec;
    p = fs::absolute(p, ec).lexically_normal();
    // "sky_{}.png" is not a file: the six it names are, each judged where it leads.
    std::vector<fs::path> named = {p};
    for (const fs::path& face : cube_wildcard_files(p.string()))
      if (!face.empty()) named.push_back(face);
    for (const fs::path& one : named) {
      if (within_roots(one, roots)) continue;
      // A symlink is named as written, then where it leads.
      const std::string as_named = (fs::path(display_path(one.parent_path())) / one.filename()).generic_string();
      const std::string leads = display_path(one);
      fail("'" + as_named + "'" + (leads == as_named ? "" : " (" + leads + ")") +
               " is outside the directories includes may read",
           f.where, line, key, "allowed: " + describe_roots(roots) + "; widen with --allow-include DIR");
    }
    return p;
  }

  void parse_channel(File& f, const std::string& name, const std::string& args, int line) {
    // The extension reads the number with parseInt: "00003" is 3. Leading
    // zeros dropped, a number longer than 3 digits is out of range, whatever
    // its first digits (reading only those made 00003 iChannel0).
    const std::string digits = name.substr(std::min(name.find_first_not_of('0', 8), name.size() - 1));
    const int n = digits.size() > 3 ? 1000 : std::stoi(digits);
    const std::string key = "#" + name;
    if (n > 3)
      fail(key + ": marchstudio binds iChannel0..iChannel3", f.where, line, key, "Shadertoy's four channels; the extension's go to 9");
    Channel& c = f.ch[static_cast<size_t>(n)];
    std::string s = args;
    const size_t b = s.find_first_not_of(" \t\r");
    s = b == std::string::npos ? "" : s.substr(b);
    std::string setting;
    if (s.rfind("::", 0) == 0) {
      size_t i = 2;
      while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
      setting = s.substr(2, i - 2);
      s = s.substr(i);
      s = s.substr(std::min(s.size(), s.find_first_not_of(" \t")));
    }
    const size_t q1 = s.find('"'), q2 = q1 == std::string::npos ? q1 : s.find('"', q1 + 1);
    const std::string shown = key + (setting.empty() ? "" : "::" + setting);
    if (q1 != 0 || q2 == std::string::npos || s.find_first_not_of(" \t\r", q2 + 1) != std::string::npos)
      fail(shown + ": expected a quoted string", f.where, line, shown,
           setting.empty() ? "e.g. " + key + " \"file://buffer.glsl\" or " + key + " \"self\"" : std::string(kDoc));
    const std::string value = s.substr(1, q2 - 1);
    const auto one_of = [&](std::initializer_list<const char*> ok, std::optional<std::string>& slot, int& at) {
      std::string list;
      for (const char* o : ok) {
        if (value == o) {
          slot = value;
          at = line;
          return;
        }
        list += std::string(list.empty() ? "" : ", ") + o;
      }
      fail(shown + ": '" + value + "' is not one of " + list, f.where, line, shown, kDoc);
    };
    if (setting == "MinFilter")
      one_of({"Nearest", "NearestMipMapNearest", "NearestMipMapLinear", "Linear", "LinearMipMapNearest", "LinearMipMapLinear"},
             c.min, c.min_line);
    else if (setting == "MagFilter") one_of({"Nearest", "Linear"}, c.mag, c.mag_line);
    else if (setting == "WrapMode") one_of({"Clamp", "Repeat", "Mirror"}, c.wrap, c.wrap_line);
    else if (setting == "Type") one_of({"Texture2D", "CubeMap"}, c.type, c.type_line);
    else if (!setting.empty())
      fail(shown + ": not a channel setting", f.where, line, shown, "MinFilter, MagFilter, WrapMode or Type");
    if (!setting.empty()) return;
    if (c.line) fail(key + ": the channel is already bound at line " + std::to_string(c.line), f.where, line, key, kDoc);
    c.line = line;
    std::string path = value;
    if (path.rfind("file://", 0) == 0) path = path.substr(7);
    else if (const size_t at = path.find("://"); at != std::string::npos)
      fail(key + ": '" + value + "' is not fetched: marchstudio renders offline from local files", f.where, line, key,
           "save it next to the shader and name it \"file://NAME\"");
    if (path.empty()) fail(key + ": an empty path", f.where, line, key, kDoc);
    if (path == "self") {
      c.self = true;
      return;
    }
    c.path = resolve(path, f, line, key);
    c.kind = kind_of(c.path);
    if (c.path == f.path) c.self = true;  // naming itself is "self", as the extension reads it
  }

  void parse(File& f, const std::string& text) {
    const std::vector<std::string> raw = line_strings(text);
    const std::vector<std::string> bare = line_strings(strip_comments(text));
    for (size_t i = 0; i < raw.size(); ++i) {
      const int line = static_cast<int>(i) + 1;
      const std::string name = i < bare.size() ? directive_name(bare[i]) : "";
      std::string out = raw[i];
      if (!name.empty()) {
        const std::string args = directive_args(raw[i], name);
        out.clear();
        if (name.rfind("iChannel", 0) == 0) parse_channel(f, name, args, line);
        else if (name == "iKeyboard") f.keyboard_line = line;
        else if (name == "iUniform") out = vscode_uniform_line(args, f.where, line);
        else if (name == "iFirstPersonControls")
          fail("#iFirstPersonControls: the extension's fly camera (iViewMatrix) is interactive and not run", f.where,
               line, "#" + name, "drive the camera from iTime or iMouse");
        else if (name == "iVertex")
          fail("#iVertex: custom vertex shaders are not run", f.where, line, "#" + name,
               "marchstudio draws a full-screen triangle; remove the line");
        // #StrictCompatibility: marchstudio always runs mainImage, so it is already so.
      }
      f.code += out + (i + 1 < raw.size() ? "\n" : "");
    }
    const std::string stripped = strip_comments(text);
    if (const size_t at = find_definition(stripped, "main"); at != std::string::npos) {
      // The extension runs main() when there is one; both would be two entry points.
      if (find_definition(stripped, "mainImage") != std::string::npos)
        fail("void main() and mainImage() both defined: the extension would run main()", f.where,
             1 + static_cast<int>(std::count(stripped.begin(), stripped.begin() + static_cast<std::ptrdiff_t>(at), '\n')),
             "main", "keep one entry point");
      f.uses_main = true;
    }
  }

  // Reads `path` and everything it names, then appends it to `order`.
  void visit(const fs::path& path, const std::string& text, const std::string& from_where, int from_line) {
    visiting.push_back(path);
    File f;
    f.path = path;
    f.where = display_path(path);
    f.from_where = from_where;
    f.from_line = from_line;
    parse(f, text);
    for (size_t n = 0; n < 4; ++n) {
      const Channel& c = f.ch[n];
      if (!c.line || c.self || c.kind != FileKind::shader) continue;
      const bool seen = std::find(visiting.begin(), visiting.end(), c.path) != visiting.end();
      if (seen) continue;  // read once, as the extension does; a cycle reads the other's last frame
      const std::string key = "#iChannel" + std::to_string(n);
      // The main file and four buffers read: a fifth is refused here,
      // before it (or any file it names) is read.
      if (visiting.size() > kMaxBuffers)
        fail("'" + display_path(c.path) + "' would be a " + std::to_string(kMaxBuffers + 1) +
                 "th buffer: marchstudio runs at most " + std::to_string(kMaxBuffers),
             f.where, c.line, key, "Shadertoy's Buffer A..D; merge two buffer files");
      const std::string problem = input_file_problem(c.path);
      if (!problem.empty()) fail(key + ": '" + display_path(c.path) + "' " + problem, f.where, c.line, key, kDoc);
      visit(c.path, read_input_file(c.path, "shader", key), f.where, c.line);
    }
    order.push_back(std::move(f));
  }
};

Sampler sampler_of(const Channel& c, const File& f, int n, Sampler s, std::vector<std::string>& warnings) {
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
void bind_channel(const std::vector<File>& files, size_t i, size_t n, ProjectInput& in,
                  std::vector<std::string>& warnings) {
  const File& f = files[i];
  const Channel& c = f.ch[n];
  const std::string key = "#iChannel" + std::to_string(n);
  if (!c.line) {
    if (c.type || c.min || c.mag || c.wrap)
      warnings.push_back(f.where + ": " + key + " has settings but no " + key + " line binds it; they do nothing");
    return;
  }
  const bool cube = c.type && *c.type == "CubeMap";
  if (c.self || c.kind == FileKind::shader) {
    if (cube) fail_input(key + "::Type \"CubeMap\": a shader's buffer is 2D", f.where, c.type_line, key + "::Type", kDoc);
    in.kind = InputKind::buffer;
    in.buffer = static_cast<int>(i);
    if (!c.self) {
      const auto other = std::find_if(files.begin(), files.end(), [&](const File& o) { return o.path == c.path; });
      in.buffer = other == files.end() ? -1 : static_cast<int>(other - files.begin());
    }
    in.sampler = sampler_of(c, f, static_cast<int>(n), {TexFilter::linear, TexWrap::clamp, false, false}, warnings);
    return;
  }
  if (c.kind == FileKind::video)
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
  if (!problem.empty()) fail_input(key + ": '" + display_path(c.path) + "' " + problem, f.where, c.line, key, kDoc);
  in.kind = c.kind == FileKind::audio ? InputKind::music : InputKind::texture;
  in.file = c.path;
  if (in.kind == InputKind::music) in.sampler = {TexFilter::linear, TexWrap::clamp, false, false};
}

// #iKeyboard: the first free channel, its line made the #define that names
// it. False when the file has no such line.
bool bind_keyboard(File& f, ProjectPass& ps) {
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
const File* reader_of_main(const std::vector<File>& files, int& line) {
  const File& main = files.back();
  for (const File& f : files)
    for (const Channel& c : f.ch)
      if (c.line && ((c.self && &f == &main) || (!c.self && c.path == main.path))) {
        line = c.line;
        return &f;
      }
  return nullptr;
}

// The Image pass that shows the main file's buffer (the last of `buffers`).
ProjectPass display_pass(const File& main, int buffers, bool any_main) {
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
  Loader l{roots, {}, {}};
  l.visit(file, text, {}, 0);
  std::vector<File>& files = l.order;  // the main file last
  const File& main = files.back();
  int reads_main_line = 0;
  const File* reads_main = reader_of_main(files, reads_main_line);
  const bool any_main = std::any_of(files.begin(), files.end(), [](const File& f) { return f.uses_main; });
  const size_t buffers = files.size() - 1 + (reads_main ? 1 : 0);
  if (buffers > 4) {
    const File& fifth = reads_main && files.size() <= 5 ? main : files[4];
    const int line = &fifth == &main ? reads_main_line : fifth.from_line;
    fail_input(std::to_string(buffers) + " buffers: marchstudio runs at most 4", &fifth == &main ? reads_main->where : fifth.from_where,
               line, "#iChannel", "Shadertoy's Buffer A..D; merge two buffer files");
  }
  ShaderProject p;
  p.origin = file;
  p.name = file.stem().string();
  bool keyboard = false;
  for (size_t i = 0; i < files.size(); ++i) {
    File& f = files[i];
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
