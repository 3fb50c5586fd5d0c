#include "shader/scene_params.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <regex>
#include <set>
#include <string>

#include "core/error.h"
#include "core/suggest.h"
#include "scene/toml_read.h"
#include "shader/assemble.h"

namespace ms {
namespace {

std::vector<float> numbers_in(const std::string& s) {
  static const std::regex num(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)");
  std::vector<float> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), num); it != std::sregex_iterator(); ++it) {
    // "vec3(" has a digit in its type name: skip numbers glued to a letter.
    const auto pos = static_cast<size_t>(it->position());
    if (pos > 0 && std::isalpha(static_cast<unsigned char>(s[pos - 1]))) continue;
    try {
      out.push_back(std::stof(it->str()));
    } catch (...) {
    }
  }
  return out;
}

// One line of GLSL as an annotated declaration; `comment` receives the text
// after "//" (kept when the initializer is rewritten).
bool parse_param_line(const std::string& line, SceneParam& p, std::string& comment) {
  static const std::regex decl(
      R"(^\s*uniform\s+(float|int|vec2|vec3|vec4)\s+([A-Za-z_]\w*)\s*(?:=\s*([^;]*))?;\s*//(.*)$)");
  static const std::regex range(R"(\brange\s*\(\s*([^,\s]+)\s*,\s*([^)\s]+)\s*\))");
  static const std::regex color(R"(\bcolou?r\b)");
  // libstdc++'s regex recurses per character and overflows the stack on
  // lines of tens of KB (minified shaders); no annotated uniform is that long.
  constexpr size_t kMaxLine = 2000;
  std::smatch m;
  if (line.size() > kMaxLine || !std::regex_match(line, m, decl)) return false;
  comment = m[4];
  p = SceneParam{};
  p.type = m[1];
  p.name = m[2];
  p.is_int = p.type == "int";
  p.components = p.type.rfind("vec", 0) == 0 ? p.type.back() - '0' : 1;
  std::smatch r;
  if (std::regex_search(comment, r, range)) {
    const std::vector<float> lo = numbers_in(r[1]), hi = numbers_in(r[2]);
    if (lo.size() != 1 || hi.size() != 1 || !(lo[0] < hi[0])) return false;
    p.lo = lo[0];
    p.hi = hi[0];
  } else if (p.type == "vec3" && std::regex_search(comment, color)) {
    p.color = true;
  } else {
    return false;  // no annotation: a plain uniform the scene sets itself
  }
  std::vector<float> init = m[3].matched ? numbers_in(m[3]) : std::vector<float>{};
  if (init.size() == 1) init.assign(p.components, init[0]);  // vec3(0.5) splats
  for (int i = 0; i < p.components; ++i) p.initial[i] = static_cast<size_t>(i) < init.size() ? init[i] : p.lo;
  p.value = p.initial;
  return true;
}

// Calls `fn(line, param, comment)` for each annotated declaration, first of
// each name only; `fn` may rewrite the line.
template <class Fn>
void for_each_param_line(std::string& text, Fn fn) {
  std::set<std::string> seen;
  std::string out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    const bool last = end == std::string::npos;
    if (last) end = text.size();
    std::string line = text.substr(start, end - start);
    SceneParam p;
    std::string comment;
    if (parse_param_line(line, p, comment) && seen.insert(p.name).second) fn(line, p, comment);
    out += line;
    if (!last) out += '\n';
    start = end + 1;
  }
  text = std::move(out);
}

// The value as a GLSL initializer of p's type, after checking it fits.
std::string initializer(const SceneParam& p, const UniformValue& v) {
  const std::string key = "--uniform " + v.name;
  const std::string what = p.type + " " + quote(p.name);
  const size_t n = static_cast<size_t>(p.components);
  if (v.values.size() != n)
    fail_input(what + " takes " + std::to_string(n) + (n == 1 ? " number" : " numbers") + ", got " +
                   std::to_string(v.values.size()),
               {}, 0, key, n == 1 ? "e.g. --uniform " + p.name + "=0.5" : "e.g. --uniform " + p.name + "=[" +
                                                                             std::string(n == 3 ? "1, 0.8, 0.6" : n == 2 ? "1, 0.5" : "1, 0.8, 0.6, 1") + "]");
  std::string range = "[" + format_number(p.lo) + ", " + format_number(p.hi) + "]";
  std::string out = n == 1 ? "" : p.type + "(";
  for (size_t i = 0; i < n; ++i) {
    const double x = v.values[i];
    if (!std::isfinite(x)) fail_input(what + " must be a finite number, got " + format_number(x), {}, 0, key);
    if (p.is_int && x != std::floor(x))
      fail_input(what + " takes a whole number, got " + format_number(x), {}, 0, key);
    // 1e3 is 1000 for an int; past int's range it would wrap or not compile.
    if (p.is_int && (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max()))
      fail_input(format_number(x) + " is out of range for int (-2147483648..2147483647)", {}, 0, key,
                 what + " is a GLSL int");
    // A float is compared as the float it becomes, as the range's bounds
    // are: 1e11 is then inside range(0, 1e11).
    const double as_set = p.is_int ? x : static_cast<double>(static_cast<float>(x));
    if (as_set < p.lo || as_set > p.hi)
      fail_input(format_number(x) + " is outside the range " + range + " of " + what, {}, 0, key,
                 p.color ? "a colour's components are in [0, 1]" : "its declaration says range(" + format_number(p.lo) +
                                                                       ", " + format_number(p.hi) + ")");
    if (i) out += ", ";
    out += p.is_int ? std::to_string(static_cast<long long>(x)) : glsl_float(static_cast<float>(x));
  }
  return n == 1 ? out : out + ")";
}

}  // namespace

std::vector<SceneParam> parse_scene_params(std::string_view glsl) {
  std::vector<SceneParam> out;
  std::string text(glsl);
  for_each_param_line(text, [&](std::string&, const SceneParam& p, const std::string&) { out.push_back(p); });
  return out;
}

std::vector<bool> set_uniform_defaults(std::string& glsl, const std::vector<UniformValue>& values) {
  std::vector<bool> found(values.size(), false);
  if (values.empty()) return found;
  for_each_param_line(glsl, [&](std::string& line, const SceneParam& p, const std::string& comment) {
    for (size_t i = 0; i < values.size(); ++i) {
      if (values[i].name != p.name) continue;
      const std::string init = initializer(p, values[i]);  // the last of repeated flags wins
      const size_t indent = line.find_first_not_of(" \t");
      line = line.substr(0, indent) + "uniform " + p.type + " " + p.name + " = " + init + ";  //" + comment;
      found[i] = true;
    }
  });
  return found;
}

void check_uniforms_found(const std::vector<UniformValue>& values, const std::vector<bool>& found,
                          const std::vector<SceneParam>& declared) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (found[i]) continue;
    std::vector<std::string_view> names;
    std::string list;
    for (const SceneParam& p : declared) {
      names.emplace_back(p.name);
      list += (list.empty() ? "" : ", ") + p.name;
    }
    if (names.empty())
      fail_input("the scene declares no ranged uniforms", {}, 0, "--uniform " + values[i].name,
                 "--uniform sets a uniform declared with a // range(lo, hi) or // color comment (docs/scene-format.md)");
    std::string hint = did_you_mean(values[i].name, names);
    hint += (hint.empty() ? "declared: " : " declared: ") + list;
    fail_input("no ranged uniform " + quote(values[i].name) + " in the scene", {}, 0, "--uniform " + values[i].name,
               hint);
  }
}

}  // namespace ms
