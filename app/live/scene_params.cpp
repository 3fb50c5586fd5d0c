#include "live/scene_params.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <string>

namespace ms::live {
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

}  // namespace

std::vector<SceneParam> parse_scene_params(std::string_view glsl) {
  static const std::regex decl(
      R"(^\s*uniform\s+(float|int|vec2|vec3|vec4)\s+([A-Za-z_]\w*)\s*(?:=\s*([^;]*))?;\s*//(.*)$)");
  static const std::regex range(R"(\brange\s*\(\s*([^,\s]+)\s*,\s*([^)\s]+)\s*\))");
  static const std::regex color(R"(\bcolou?r\b)");
  std::vector<SceneParam> out;
  std::set<std::string> seen;
  size_t start = 0;
  while (start <= glsl.size()) {
    size_t end = glsl.find('\n', start);
    if (end == std::string_view::npos) end = glsl.size();
    const std::string line(glsl.substr(start, end - start));
    start = end + 1;
    // libstdc++'s regex recurses per character and overflows the stack on
    // lines of tens of KB (minified shaders); no annotated uniform is that long.
    constexpr size_t kMaxLine = 2000;
    std::smatch m;
    if (line.size() > kMaxLine || !std::regex_match(line, m, decl)) continue;
    const std::string comment = m[4];
    SceneParam p;
    p.type = m[1];
    p.name = m[2];
    p.is_int = p.type == "int";
    p.components = p.type.rfind("vec", 0) == 0 ? p.type.back() - '0' : 1;
    std::smatch r;
    if (std::regex_search(comment, r, range)) {
      const std::vector<float> lo = numbers_in(r[1]), hi = numbers_in(r[2]);
      if (lo.size() != 1 || hi.size() != 1 || !(lo[0] < hi[0])) continue;
      p.lo = lo[0];
      p.hi = hi[0];
    } else if (p.type == "vec3" && std::regex_search(comment, color)) {
      p.color = true;
    } else {
      continue;  // no annotation: a plain uniform the scene sets itself
    }
    if (seen.count(p.name)) continue;
    std::vector<float> init = m[3].matched ? numbers_in(m[3]) : std::vector<float>{};
    if (init.size() == 1) init.assign(p.components, init[0]);  // vec3(0.5) splats
    for (int i = 0; i < p.components; ++i)
      p.initial[i] = static_cast<size_t>(i) < init.size() ? init[i] : p.lo;
    p.value = p.initial;
    seen.insert(p.name);
    out.push_back(p);
  }
  return out;
}

void carry_over_values(std::vector<SceneParam>& fresh, const std::vector<SceneParam>& old) {
  for (SceneParam& p : fresh) {
    auto it = std::find_if(old.begin(), old.end(), [&](const SceneParam& o) { return o.name == p.name; });
    if (it != old.end() && it->type == p.type && it->initial == p.initial) p.value = it->value;
  }
}

}  // namespace ms::live
