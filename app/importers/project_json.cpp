#include "importers/project_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "core/error.h"
#include "importers/json_brief.h"

namespace ms {
namespace {

using json = nlohmann::json;

// The line each value of a JSON text starts on, by its key path
// ("Shader.renderpass[1].inputs[0].ctype"): nlohmann keeps no positions,
// and an error should name a line. Paths are kept as hashes, each made
// from its parent's in the time of its own last part, so memory and time
// are linear in the text even for 40,000 nested arrays (full path
// strings would be quadratic in depth). A collision could only misplace
// an error's line number.
class JsonLines {
 public:
  explicit JsonLines(std::string_view t) {
    struct Frame {
      bool array = false;
      int index = 0;
      bool want_key = true;
      std::string key;
      PathHash path;
    };
    std::vector<Frame> stack;
    int line = 1;
    auto path_here = [&]() -> PathHash {
      if (stack.empty()) return {};
      const Frame& f = stack.back();
      if (f.array) return f.path.add("[" + std::to_string(f.index) + "]");
      return (f.path.empty ? f.path : f.path.add(".")).add(f.key);
    };
    for (size_t i = 0; i < t.size(); ++i) {
      const char c = t[i];
      if (c == '\n') ++line;
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ':') continue;
      if (c == ',') {
        if (!stack.empty()) {
          ++stack.back().index;
          stack.back().want_key = true;
        }
        continue;
      }
      if (c == '}' || c == ']') {
        if (!stack.empty()) stack.pop_back();
        continue;
      }
      const bool is_key = !stack.empty() && !stack.back().array && stack.back().want_key && c == '"';
      std::string s;
      if (c == '"') {
        for (++i; i < t.size() && t[i] != '"'; ++i) {
          if (t[i] == '\\' && i + 1 < t.size()) ++i;
          if (t[i] == '\n') ++line;
          s.push_back(t[i]);
        }
      }
      if (is_key) {
        stack.back().key = s;
        stack.back().want_key = false;
        continue;
      }
      const PathHash here = path_here();
      lines_.emplace(here.h, line);
      if (c == '{' || c == '[') {
        Frame f;
        f.array = c == '[';
        f.path = here;
        stack.push_back(f);
      } else if (c != '"') {
        while (i + 1 < t.size() && std::string_view(",}] \t\r\n").find(t[i + 1]) == std::string_view::npos) ++i;
      }
    }
  }
  int line(const std::string& path) const {
    const auto it = lines_.find(PathHash{}.add(path).h);
    return it == lines_.end() ? 0 : it->second;
  }

 private:
  // A polynomial hash of the path's bytes modulo 2^61 - 1, extended a part
  // at a time; `empty` while no byte is in it.
  struct PathHash {
    std::uint64_t h = 0;
    bool empty = true;
    PathHash add(std::string_view part) const {
      constexpr std::uint64_t kMod = (std::uint64_t{1} << 61) - 1, kBase = 1000003;
      PathHash r = *this;
      for (const char ch : part) {
        const unsigned __int128 v = static_cast<unsigned __int128>(r.h) * kBase + static_cast<unsigned char>(ch) + 1;
        r.h = static_cast<std::uint64_t>(v % kMod);
        r.empty = false;
      }
      return r;
    }
  };
  std::unordered_map<std::uint64_t, int> lines_;
};

class Loader {
 public:
  Loader(std::string_view text, const std::string& display) : lines_(text), file_(display) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what, const std::string& hint = {}) const {
    fail_input(what, file_, lines_.line(path), path, hint);
  }

  std::string str(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "'" + path + "' must be a string");
    return j.get<std::string>();
  }

  // Shadertoy writes booleans and numbers as strings ("true", "0").
  bool flag(const json& j, const std::string& path) const {
    if (j.is_boolean()) return j.get<bool>();
    if (j.is_string() && (j == "true" || j == "false")) return j == "true";
    fail(path, "'" + path + "' must be true or false");
  }
  // The value as a whole number, never narrowed: callers range-check it
  // (get<int>() read 4294967297 as 1).
  long long integer(const json& j, const std::string& path) const {
    if (const std::optional<long long> v = whole(j)) return *v;
    if (j.is_string()) {
      const std::string s = j.get<std::string>();
      if (!s.empty() && s.size() <= 18 && s.find_first_not_of("0123456789") == std::string::npos) return std::stoll(s);
    }
    fail(path, "'" + path + "' must be a whole number", "at most 18 digits");
  }

  // A JSON integer that fits a long long, else nothing (a float, or
  // 2^64-1 as nlohmann's unsigned).
  static std::optional<long long> whole(const json& j) {
    if (j.is_number_unsigned()) {
      const std::uint64_t u = j.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(std::numeric_limits<long long>::max())) return std::nullopt;
      return static_cast<long long>(u);
    }
    if (j.is_number_integer()) return j.get<std::int64_t>();
    return std::nullopt;
  }

  // A buffer named by id (257..260, or the site's string ids) or by the
  // previz file ("/media/previz/buffer00.png" .. buffer03), or -1.
  static int buffer_of(const json& id, const std::string& file) {
    if (const std::optional<long long> n = whole(id); n && *n >= 257 && *n <= 260) return static_cast<int>(*n - 257);
    if (id.is_string()) {
      static const char* ids[] = {"4dXGR8", "XsXGR8", "4sXGR8", "XdfGR8"};
      for (int i = 0; i < 4; ++i)
        if (id == ids[i]) return i;
      const std::string s = id.get<std::string>();
      if (s.size() == 3 && s.find_first_not_of("0123456789") == std::string::npos && std::stoi(s) >= 257 &&
          std::stoi(s) <= 260)
        return std::stoi(s) - 257;
    }
    const size_t at = file.find("/media/previz/buffer0");
    if (at != std::string::npos && at + 22 <= file.size() && file[at + 21] >= '0' && file[at + 21] <= '3')
      return file[at + 21] - '0';
    return -1;
  }

  // Cube A, by id (41, or the site's "4dX3Rr") or its previz file.
  static bool is_cube_a(const json& id, const std::string& file) {
    if (whole(id) == 41LL || (id.is_string() && (id == "4dX3Rr" || id == "41")))
      return true;
    return file.find("/media/previz/cubemap00.png") != std::string::npos;
  }

  InputKind kind_of(const std::string& ctype, const std::string& path) const {
    static const std::map<std::string, InputKind> kinds = {
        {"buffer", InputKind::buffer},   {"texture", InputKind::texture},         {"keyboard", InputKind::keyboard},
        {"cubemap", InputKind::cubemap}, {"volume", InputKind::volume},           {"music", InputKind::music},
        {"musicstream", InputKind::musicstream}, {"mic", InputKind::mic},         {"video", InputKind::video},
        {"webcam", InputKind::webcam}};
    const auto it = kinds.find(ctype);
    if (it == kinds.end())
      fail(path, "unknown input type '" + ctype + "'",
           "one of buffer, texture, keyboard, cubemap, volume, music, musicstream, mic, video, webcam");
    return it->second;
  }

  Sampler sampler(const json& in, InputKind kind, const std::string& path) const {
    Sampler s;
    if (kind == InputKind::texture || kind == InputKind::volume) {  // Shadertoy's defaults for a texture
      s.filter = TexFilter::mipmap;
      s.wrap = TexWrap::repeat;
      s.vflip = true;
    }
    if (kind == InputKind::video) s.vflip = true;  // Shadertoy's video default: linear, clamp, vflip
    if (!in.contains("sampler")) return s;
    const json& j = in["sampler"];
    const std::string p = path + ".sampler";
    if (!j.is_object()) fail(p, "'" + p + "' must be an object");
    if (j.contains("filter")) {
      const std::string f = str(j["filter"], p + ".filter");
      if (f == "nearest") s.filter = TexFilter::nearest;
      else if (f == "linear") s.filter = TexFilter::linear;
      else if (f == "mipmap") s.filter = TexFilter::mipmap;
      else fail(p + ".filter", "unknown filter '" + f + "'", "nearest, linear or mipmap");
    }
    if (j.contains("wrap")) {
      const std::string w = str(j["wrap"], p + ".wrap");
      if (w == "clamp") s.wrap = TexWrap::clamp;
      else if (w == "repeat") s.wrap = TexWrap::repeat;
      else fail(p + ".wrap", "unknown wrap '" + w + "'", "clamp or repeat");
    }
    if (j.contains("vflip")) s.vflip = flag(j["vflip"], p + ".vflip");
    if (j.contains("srgb")) s.srgb = flag(j["srgb"], p + ".srgb");
    return s;
  }

  ProjectInput input(const json& in, const std::string& path, int& channel) const {
    if (!in.is_object()) fail(path, "'" + path + "' must be an object");
    ProjectInput out;
    const json& type = in.contains("ctype") ? in["ctype"] : in.contains("type") ? in["type"] : json();
    if (type.is_null()) fail(path, "'" + path + "' has no ctype", "each input says what it reads");
    out.kind = kind_of(str(type, path + (in.contains("ctype") ? ".ctype" : ".type")), path + ".ctype");
    if (!in.contains("channel")) fail(path, "'" + path + "' has no channel");
    const long long n = integer(in["channel"], path + ".channel");
    if (n < 0 || n > 3) fail(path + ".channel", "channel " + std::to_string(n) + " is out of range", "iChannel0..iChannel3");
    channel = static_cast<int>(n);
    const std::string src = in.contains("src") && in["src"].is_string()           ? in["src"].get<std::string>()
                            : in.contains("filepath") && in["filepath"].is_string() ? in["filepath"].get<std::string>()
                                                                                  : "";
    out.src = src;
    if (out.kind == InputKind::buffer) {
      out.buffer = buffer_of(in.contains("id") ? in["id"] : json(), src);
      if (out.buffer < 0) fail(path, "a buffer input that names no buffer A..D", "its id is 257..260 (A..D)");
    }
    if (out.kind == InputKind::cubemap && is_cube_a(in.contains("id") ? in["id"] : json(), src)) out.buffer = kCubeA;
    if (out.kind == InputKind::cubemap && out.buffer != kCubeA && src.empty())
      fail(path, "a cubemap input without a src", "its src names face 0 (/media/a/<hash>.jpg), or its id is Cube A's");
    if (out.kind == InputKind::texture && src.empty()) fail(path, "a texture input without a src");
    if (out.kind == InputKind::volume && src.empty()) fail(path, "a volume input without a src");
    out.sampler = sampler(in, out.kind, path);
    return out;
  }

  ShaderProject load(const json& root) {
    ShaderProject p;
    std::string prefix;
    const json& shader = shader_of(root, p, prefix);
    if (shader.contains("info") && shader["info"].is_object() && shader["info"].contains("name") &&
        shader["info"]["name"].is_string())
      p.name = shader["info"]["name"].get<std::string>();
    const json& passes = shader["renderpass"];
    std::vector<ProjectPass> buffers;
    std::optional<ProjectPass> image;
    bool cube_seen = false;
    for (size_t i = 0; i < passes.size(); ++i) {
      const std::string path = prefix + "renderpass[" + std::to_string(i) + "]";
      const json& rp = passes[i];
      if (!rp.is_object() || !rp.contains("type")) fail(path, "'" + path + "' has no type");
      const std::string type = str(rp["type"], path + ".type");
      ProjectPass pass;
      pass.name = rp.contains("name") && rp["name"].is_string() ? rp["name"].get<std::string>()
                  : type == "image"                              ? "Image"
                                                                 : type;
      if (rp.contains("code")) pass.code = str(rp["code"], path + ".code");
      pass.where = file_ + " (" + pass.name + ")";
      if (type == "common") {
        p.common = pass.code;
        p.common_where = file_ + " (Common)";
        continue;
      }
      if (type == "sound") {
        p.has_sound = true;  // it never changes the image: said, not refused, so the picture still renders
        p.warnings.push_back("its Sound pass (mainSound) is not run: marchstudio renders the image, not audio");
        continue;
      }
      if (type != "image" && type != "buffer" && type != "cubemap")
        fail(path + ".type", "unknown pass type '" + type + "'", "image, buffer, common, sound or cubemap");
      read_inputs(rp, path, pass);
      if (type == "image") {
        if (image) fail(path + ".type", "more than one Image pass");
        pass.kind = PassKind::image;
        image = std::move(pass);
      } else if (type == "cubemap") {  // Cube A: after the buffers, before the Image pass
        if (cube_seen) fail(path + ".type", "more than one cubemap pass", "Shadertoy has one, Cube A");
        cube_seen = true;
        pass.kind = PassKind::cube;
        pass.output = kCubeA;
        if (!rp.contains("name")) pass.name = "Cube A";
        pass.where = file_ + " (" + pass.name + ")";
        buffers.push_back(std::move(pass));
      } else {
        set_buffer_output(rp, path, pass);
        buffers.push_back(std::move(pass));
      }
    }
    if (!image) fail(prefix + "renderpass", "the shader has no Image pass");
    // Shadertoy runs the buffers A, B, C, D, then Cube A, then the Image, whatever the file's order.
    std::stable_sort(buffers.begin(), buffers.end(),
                     [](const ProjectPass& a, const ProjectPass& b) { return a.output < b.output; });
    for (size_t i = 1; i < buffers.size(); ++i)
      if (buffers[i].output == buffers[i - 1].output)
        fail(prefix + "renderpass", "two passes write Buffer " + buffer_letter(buffers[i].output),
             "each buffer has one pass that draws it");
    p.passes = std::move(buffers);
    p.passes.push_back(std::move(*image));
    return p;
  }

 private:
  // The shader object of the API's {"Shader": ...}, or the first of the
  // site's export array; `prefix` its JSON path ("Shader.", "[0].").
  const json& shader_of(const json& root, ShaderProject& p, std::string& prefix) {
    const json* shader = &root;
    if (root.is_array()) {
      if (root.empty()) fail({}, "the file holds no shader");
      if (root.size() > 1)
        p.warnings.push_back(file_ + " holds " + std::to_string(root.size()) + " shaders; rendering the first");
      shader = &root[0];
      prefix = "[0].";
    } else if (root.is_object() && root.contains("Shader")) {
      shader = &root["Shader"];
      prefix = "Shader.";
    } else if (root.is_object() && root.contains("Error")) {
      fail("Error", "the file is an error from the Shadertoy API: " + json_brief(root["Error"], 200), "download the shader again");
    }
    if (!shader->is_object() || !shader->contains("renderpass") || !(*shader)["renderpass"].is_array())
      fail(prefix + "renderpass", "no 'renderpass' array: this is not Shadertoy JSON",
           "expected {\"Shader\": {\"renderpass\": [...]}} or the site's export, an array of shaders");
    return *shader;
  }

  // A pass's "inputs", each on its channel, at most one per channel.
  void read_inputs(const json& rp, const std::string& path, ProjectPass& pass) {
    if (!rp.contains("inputs")) return;
    if (!rp["inputs"].is_array()) fail(path + ".inputs", "'inputs' must be an array");
    for (size_t k = 0; k < rp["inputs"].size(); ++k) {
      const std::string ip = path + ".inputs[" + std::to_string(k) + "]";
      int channel = 0;
      ProjectInput in = input(rp["inputs"][k], ip, channel);
      if (pass.inputs[channel].kind != InputKind::none)
        fail(ip + ".channel", pass.name + " has two inputs on iChannel" + std::to_string(channel));
      pass.inputs[channel] = std::move(in);
    }
  }

  // A buffer pass's output, A..D: its output id, else its name "Buffer X".
  void set_buffer_output(const json& rp, const std::string& path, ProjectPass& pass) {
    pass.kind = PassKind::buffer;
    const json out = rp.contains("outputs") && rp["outputs"].is_array() && !rp["outputs"].empty() &&
                             rp["outputs"][0].is_object() && rp["outputs"][0].contains("id")
                         ? rp["outputs"][0]["id"]
                         : json();
    pass.output = buffer_of(out, "");
    if (pass.output < 0 && pass.name.size() == 8 && pass.name.rfind("Buffer ", 0) == 0 && pass.name[7] >= 'A' &&
        pass.name[7] <= 'D')
      pass.output = pass.name[7] - 'A';
    if (pass.output < 0) fail(path + ".outputs", pass.name + " writes no buffer A..D", "its output id is 257..260");
    if (!rp.contains("name")) pass.name = "Buffer " + buffer_letter(pass.output);
    pass.where = file_ + " (" + pass.name + ")";
  }

  const JsonLines lines_;
  const std::string file_;
};

}  // namespace

ShaderProject load_shadertoy_json(std::string_view text, const std::string& display) {
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // Line and column of the byte where parsing stopped.
    const size_t at = std::min(e.byte > 0 ? e.byte - 1 : 0, text.size());
    const std::string_view before = text.substr(0, at);
    const int line = 1 + static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    const size_t nl = before.rfind('\n');
    const size_t col = at - (nl == std::string_view::npos ? 0 : nl + 1) + 1;
    std::string what = e.what();
    const size_t colon = what.rfind(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    fail_input("malformed JSON at column " + std::to_string(col) + ": " + what, display, line);
  } catch (const json::exception& e) {  // a number past double's range (out_of_range.406): no position given
    std::string what = e.what();
    const size_t bracket = what.find("] ");
    fail_input("malformed JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)), display);
  }
  ShaderProject p = Loader(text, display).load(root);
  check_project(p, display);
  return p;
}

}  // namespace ms
