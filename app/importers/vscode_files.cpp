#include "importers/vscode_files.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/error.h"
#include "importers/vscode.h"
#include "io/cube_faces.h"
#include "io/image_io.h"
#include "io/input_file.h"
#include "io/path_roots.h"
#include "preprocess/directive.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxBuffers = 4;  // Shadertoy's Buffer A..D

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

// The extension sorts an input by its MIME type: image, audio, or (any
// other, text included) a shader.
VsKind kind_of(const fs::path& p) {
  const std::string e = lower_extension(p);
  if (is_image_name(p)) return VsKind::image;
  for (const char* x : {".mp3", ".wav", ".ogg", ".oga", ".flac", ".m4a", ".aac", ".opus"})
    if (e == x) return VsKind::audio;
  for (const char* x : {".mp4", ".webm", ".ogv", ".mov", ".mkv", ".avi"})
    if (e == x) return VsKind::video;
  return VsKind::shader;
}

struct Loader {
  const std::vector<fs::path>& roots;
  std::vector<VsFile> order;      // post-order: a file after the files it reads
  std::vector<fs::path> visiting;

  [[noreturn]] void fail(const std::string& what, const std::string& where, int line, const std::string& key,
                         const std::string& hint = kVscodeDoc) {
    fail_input(what, where, line, key, hint);
  }

  fs::path resolve(const std::string& given, const VsFile& f, int line, const std::string& key) {
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

  void parse_channel(VsFile& f, const std::string& name, const std::string& args, int line) {
    // The extension reads the number with parseInt: "00003" is 3. Leading
    // zeros dropped, a number longer than 3 digits is out of range, whatever
    // its first digits (reading only those made 00003 iChannel0).
    const std::string digits = name.substr(std::min(name.find_first_not_of('0', 8), name.size() - 1));
    const int n = digits.size() > 3 ? 1000 : std::stoi(digits);
    const std::string key = "#" + name;
    if (n > 3)
      fail(key + ": marchstudio binds iChannel0..iChannel3", f.where, line, key, "Shadertoy's four channels; the extension's go to 9");
    VsChannel& c = f.ch[static_cast<size_t>(n)];
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
           setting.empty() ? "e.g. " + key + " \"file://buffer.glsl\" or " + key + " \"self\"" : std::string(kVscodeDoc));
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
      fail(shown + ": '" + value + "' is not one of " + list, f.where, line, shown, kVscodeDoc);
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
    if (c.line) fail(key + ": the channel is already bound at line " + std::to_string(c.line), f.where, line, key, kVscodeDoc);
    c.line = line;
    std::string path = value;
    if (path.rfind("file://", 0) == 0) path = path.substr(7);
    else if (const size_t at = path.find("://"); at != std::string::npos)
      fail(key + ": '" + value + "' is not fetched: marchstudio renders offline from local files", f.where, line, key,
           "save it next to the shader and name it \"file://NAME\"");
    if (path.empty()) fail(key + ": an empty path", f.where, line, key, kVscodeDoc);
    if (path == "self") {
      c.self = true;
      return;
    }
    c.path = resolve(path, f, line, key);
    c.kind = kind_of(c.path);
    if (c.path == f.path) c.self = true;  // naming itself is "self", as the extension reads it
  }

  void parse(VsFile& f, const std::string& text) {
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
    VsFile f;
    f.path = path;
    f.where = display_path(path);
    f.from_where = from_where;
    f.from_line = from_line;
    parse(f, text);
    for (size_t n = 0; n < 4; ++n) {
      const VsChannel& c = f.ch[n];
      if (!c.line || c.self || c.kind != VsKind::shader) continue;
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
      if (!problem.empty()) fail(key + ": '" + display_path(c.path) + "' " + problem, f.where, c.line, key, kVscodeDoc);
      visit(c.path, read_input_file(c.path, "shader", key), f.where, c.line);
    }
    order.push_back(std::move(f));
  }
};

}  // namespace

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

std::vector<VsFile> read_vscode_files(const std::string& text, const fs::path& file, const std::vector<fs::path>& roots) {
  Loader l{roots, {}, {}};
  l.visit(file, text, {}, 0);
  return std::move(l.order);
}

}  // namespace ms
