#include "scene/writeback.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <variant>

#include <toml++/toml.h>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "core/error.h"
#include "scene/quality_fields.h"
#include "scene/toml_guard.h"

namespace ms {
namespace fs = std::filesystem;

std::string toml_float(float v) {
  if (!std::isfinite(v)) fail_input("cannot write a non-finite number into a scene file");
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, end);
  // "100" would read back as an integer; "1e-04" is already a TOML float.
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string toml_int(int v) { return std::to_string(v); }
std::string toml_bool(bool v) { return v ? "true" : "false"; }

std::string toml_vec3(glm::vec3 v) {
  return "[" + toml_float(v.x) + ", " + toml_float(v.y) + ", " + toml_float(v.z) + "]";
}

std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

namespace {

toml::table parse(std::string_view text, const std::string& name) {
  check_toml_key_depth(text, name);  // toml++ recurses per dotted key component
#if TOML_EXCEPTIONS
  try {
    return toml::parse(text, std::string_view{name});
  } catch (const toml::parse_error& e) {
    fail_input("invalid TOML: " + std::string(e.description()), name, static_cast<int>(e.source().begin.line));
  }
#else
  toml::parse_result r = toml::parse(text, std::string_view{name});
  if (!r) fail_input("invalid TOML: " + std::string(r.error().description()), name,
                     static_cast<int>(r.error().source().begin.line));
  return std::move(r).table();
#endif
}

// toml++ positions are 1-based lines and 1-based columns counted in code
// points; turn them into byte offsets of `text`.
class Offsets {
 public:
  explicit Offsets(std::string_view text) : text_(text) {
    starts_.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  size_t at(const toml::source_position& p) const {
    size_t off = line_start(p.line);
    for (toml::source_index col = 1; col < p.column && off < text_.size(); ++col) {
      ++off;  // past the lead byte, then past continuation bytes
      while (off < text_.size() && (static_cast<unsigned char>(text_[off]) & 0xC0) == 0x80) ++off;
    }
    return off;
  }
  size_t line_start(toml::source_index line) const {
    return line >= 1 && line <= starts_.size() ? starts_[line - 1] : text_.size();
  }
  // Offset just past the '\n' ending `line` (or the end of the text).
  size_t next_line(toml::source_index line) const { return line_start(line + 1); }

 private:
  std::string_view text_;
  std::vector<size_t> starts_;
};

bool before(const toml::source_position& a, const toml::source_position& b) {
  return a.line != b.line ? a.line < b.line : a.column < b.column;
}

// Whether `a` and `b` hold the same value as the scene reads it: numbers
// as 32-bit floats (`fov = 50` is the 50.0 a camera edit writes), arrays
// element by element, anything else by type and value.
bool same_value(const toml::node& a, const toml::node& b) {
  if ((a.is_integer() || a.is_floating_point()) && (b.is_integer() || b.is_floating_point())) {
    if (a.is_integer() && b.is_integer()) return a.as_integer()->get() == b.as_integer()->get();
    return static_cast<float>(a.value<double>().value_or(0.0)) == static_cast<float>(b.value<double>().value_or(0.0));
  }
  if (const toml::array* x = a.as_array()) {
    const toml::array* y = b.as_array();
    if (!y || x->size() != y->size()) return false;
    for (std::size_t i = 0; i < x->size(); ++i)
      if (!same_value(*x->get(i), *y->get(i))) return false;
    return true;
  }
  if (a.type() != b.type() || a.is_table()) return false;
  if (a.is_string()) return a.as_string()->get() == b.as_string()->get();
  if (a.is_boolean()) return a.as_boolean()->get() == b.as_boolean()->get();
  return false;
}

// An edit's value text as a node (its owner keeps it alive); null when it
// does not parse alone.
const toml::node* edit_value(const std::string& value, toml::table& owner) {
#if TOML_EXCEPTIONS
  try {
    owner = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    return nullptr;
  }
#else
  toml::parse_result r = toml::parse("v = " + value);
  if (!r) return nullptr;
  owner = std::move(r).table();
#endif
  return owner.get("v");
}

std::string apply_one(const std::string& text, const TomlEdit& e, const std::string& name) {
  toml::table root = parse(text, name);
  const Offsets off(text);
  std::string out = text;
  const std::string what = e.index >= 0 ? e.table + "[" + std::to_string(e.index) + "]" : e.table;

  toml::table* t = nullptr;
  if (e.index >= 0) {
    toml::array* arr = root[e.table].as_array();
    if (!arr || static_cast<size_t>(e.index) >= arr->size() || !(*arr)[e.index].as_table())
      fail_input("cannot write '" + what + "." + e.key + "': the file has no such entry", name, 0, what);
    t = (*arr)[e.index].as_table();
  } else if (toml::node* n = root.get(e.table)) {
    t = n->as_table();
    if (!t) fail_input("cannot write '" + e.table + "." + e.key + "': '" + e.table + "' is not a table", name, 0,
                       e.table);
  } else {
    // No such table yet: a new section at the end of the file.
    if (!out.empty() && out.back() != '\n') out += '\n';
    return out + "\n[" + e.table + "]\n" + e.key + " = " + e.value + "\n";
  }

  if (toml::node* v = t->get(e.key)) {
    toml::table parsed;
    const toml::node* now = edit_value(e.value, parsed);
    if (now && same_value(*v, *now)) return out;  // unchanged: the file's own text stays
    const size_t b = off.at(v->source().begin), en = off.at(v->source().end);
    return out.replace(b, en - b, e.value);
  }

  // Absent key: after the table's last key/value.
  const toml::key* last_key = nullptr;
  const toml::node* last_val = nullptr;
  for (auto&& [k, v] : *t) {
    if (!last_val || before(last_val->source().end, v.source().end)) {
      last_key = &k;
      last_val = &v;
    }
  }
  if (t->is_inline()) {
    if (last_val) return out.insert(off.at(last_val->source().end), ", " + e.key + " = " + e.value);
    return out.insert(off.at(t->source().begin) + 1, " " + e.key + " = " + e.value + " ");  // after '{'
  }
  if (!last_val) {  // an empty [table] or [[entry]]: right under its header
    return out.insert(off.next_line(t->source().begin.line), e.key + " = " + e.value + "\n");
  }
  // Copy the sibling's indentation and any dotted prefix ("camera." in
  // `camera.fov = 30`) so the new line lands in the same table.
  const size_t line_b = off.line_start(last_key->source().begin.line);
  const std::string prefix = out.substr(line_b, off.at(last_key->source().begin) - line_b);
  size_t at = off.next_line(last_val->source().end.line);
  std::string line = prefix + e.key + " = " + e.value + "\n";
  if (at == out.size() && !out.empty() && out.back() != '\n') line = "\n" + line;
  return out.insert(at, line);
}

std::string read_text(const fs::path& file) { return read_input_file(file, "scene file"); }

}  // namespace

std::string apply_toml_edits(std::string_view text, const std::vector<TomlEdit>& edits,
                             const std::string& display_name) {
  std::string out(text);
  // One at a time: each edit re-parses, so positions are never stale.
  for (const TomlEdit& e : edits) out = apply_one(out, e, display_name);
  parse(out, display_name);  // never hand back text that does not read
  return out;
}

void write_toml_edits(const fs::path& file, const std::vector<TomlEdit>& edits, const TomlCheck& check) {
  const std::string text = apply_toml_edits(read_text(file), edits, file.string());
  if (check) check(text);
  struct stat st {};
  const int mode = ::stat(file.c_str(), &st) == 0 ? static_cast<int>(st.st_mode & 07777) : -1;
  write_file_atomic(file, text, mode);  // the user's permissions are kept
}

std::vector<TomlEdit> camera_edits(const Camera& cam) {
  return {{"camera", -1, "position", toml_vec3(cam.position)},
          {"camera", -1, "target", toml_vec3(cam.target)},
          {"camera", -1, "up", toml_vec3(cam.up)},
          {"camera", -1, "fov", toml_float(cam.fov_deg)}};
}

namespace {

// Collects an edit for each field whose value changed.
struct Differ {
  std::vector<TomlEdit>& out;
  std::string table;
  int index = -1;
  void num(const char* key, float a, float b) {
    if (a != b) out.push_back({table, index, key, toml_float(b)});
  }
  void count(const char* key, int a, int b) {
    if (a != b) out.push_back({table, index, key, toml_int(b)});
  }
  void flag(const char* key, bool a, bool b) {
    if (a != b) out.push_back({table, index, key, toml_bool(b)});
  }
  void vec(const char* key, glm::vec3 a, glm::vec3 b) {
    if (a != b) out.push_back({table, index, key, toml_vec3(b)});
  }
  // A field of any of the types a TOML table holds (scene/toml_read.h's Field).
  void any(std::string_view key, float a, float b) { num(std::string(key).c_str(), a, b); }
  void any(std::string_view key, int a, int b) { count(std::string(key).c_str(), a, b); }
  void any(std::string_view key, bool a, bool b) { flag(std::string(key).c_str(), a, b); }
  void any(std::string_view key, glm::vec3 a, glm::vec3 b) { vec(std::string(key).c_str(), a, b); }
};

}  // namespace

std::vector<TomlEdit> scene_value_edits(const Scene& before, const Scene& after) {
  std::vector<TomlEdit> out;
  Differ q{out, "quality"};
  for (const Field<Quality>& f : kQualityFields)  // every [quality] key, as the loader reads them
    std::visit([&](auto member) { q.any(f.key, before.quality.*member, after.quality.*member); }, f.member);
  Differ sky{out, "sky"};
  sky.vec("horizon", before.sky.horizon, after.sky.horizon);
  sky.vec("zenith", before.sky.zenith, after.sky.zenith);
  sky.vec("ambient", before.sky.ambient, after.sky.ambient);
  Differ render{out, "render"};
  render.num("exposure", before.render.exposure, after.render.exposure);

  for (size_t k = 0; k < after.lights.size() && k < before.lights.size(); ++k) {
    const Light &a = before.lights[k], &b = after.lights[k];
    Differ d{out, "lights", static_cast<int>(k)};
    if (b.kind == LightKind::point) {
      d.vec("position", a.position, b.position);
      d.vec("attenuation", a.attenuation, b.attenuation);
    } else {
      d.vec("direction", a.direction, b.direction);
    }
    d.vec("color", a.color, b.color);
    d.num("intensity", a.intensity, b.intensity);
    d.num("size", a.size, b.size);
  }
  for (size_t k = 0; k < after.materials.size() && k < before.materials.size(); ++k) {
    const Material &a = before.materials[k], &b = after.materials[k];
    Differ d{out, "materials", static_cast<int>(k)};
    d.vec("color", a.color, b.color);
    d.num("ambient", a.ambient, b.ambient);
    d.num("diffuse", a.diffuse, b.diffuse);
    d.num("specular", a.specular, b.specular);
    d.num("shininess", a.shininess, b.shininess);
    d.num("reflectivity", a.reflectivity, b.reflectivity);
    if (b.pattern == Pattern::checker) {
      d.vec("color2", a.color2, b.color2);
      d.num("pattern_scale", a.pattern_scale, b.pattern_scale);
      d.vec("pattern_velocity", a.pattern_velocity, b.pattern_velocity);
    }
  }
  return out;
}

}  // namespace ms
