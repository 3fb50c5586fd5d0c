// `#iUniform` lines of the VS Code Shader Toy extension as marchstudio's
// annotated uniforms (shader/scene_params.h). The extension's grammar:
//   #iUniform <type> <name> [= <value>] [in { <min>, <max> }] [step <value>]
// with <type> float, int, vec2..vec4, ivec2..ivec4 or color3, and a value a
// number or a constructor of numbers.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "importers/vscode.h"

namespace ms {
namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The numbers of "1.5", "-2" or "vec3(1, 2, 3)"; false for anything else.
bool parse_value(const std::string& text, std::vector<double>& out) {
  std::string s = trim(text);
  out.clear();
  if (!s.empty() && std::isalpha(static_cast<unsigned char>(s[0]))) {
    size_t i = 0;
    while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
    const std::string ctor = s.substr(0, i);
    const std::string rest = trim(s.substr(i));
    if (rest.size() < 2 || rest.front() != '(' || rest.back() != ')') return false;
    if (ctor != "float" && ctor != "int" && ctor != "vec2" && ctor != "vec3" && ctor != "vec4" && ctor != "color3" &&
        ctor != "ivec2" && ctor != "ivec3" && ctor != "ivec4")
      return false;
    s = rest.substr(1, rest.size() - 2);
  }
  std::stringstream parts(s);
  std::string part;
  while (std::getline(parts, part, ',')) {
    const std::string t = trim(part);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v)) return false;
    out.push_back(v);
  }
  return !out.empty();
}

std::string number(double v, bool is_int) {
  std::ostringstream o;
  if (is_int) {
    o << static_cast<long long>(v);
    return o.str();
  }
  o.precision(9);
  o << v;
  std::string s = o.str();
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string format_int_range(double v) {
  std::ostringstream o;
  o << v;
  return o.str() + " is out of range for int (-2147483648..2147483647)";
}

// The one-line error of an #iUniform line, blamed on its file and line.
struct LineError {
  const std::string& where;
  int line;
  [[noreturn]] void operator()(const std::string& what, const std::string& hint = {}) const {
    fail_input(what, where, line, "#iUniform",
               hint.empty() ? "the extension's form: #iUniform float name = 1.0 in { 0.0, 5.0 } (docs/vscode.md)" : hint);
  }
};

// What follows the name, split at its keywords: "= v", "in { a, b }",
// "step s", "sequencer {...}".
struct UniformTail {
  std::string def, lo_text, hi_text;
};

// "in { min, max }" at the start of `rest`: min and max, split at the comma
// outside parentheses; `rest` keeps what follows the '}'.
void read_range(std::string& rest, UniformTail& t, const LineError& fail) {
  const size_t open = rest.find('{'), close = rest.find('}');
  if (open == std::string::npos || close == std::string::npos || close < open) fail("expected 'in { min, max }'");
  const std::string range = rest.substr(open + 1, close - open - 1);
  int depth = 0;
  size_t split = std::string::npos;
  for (size_t i = 0; i < range.size(); ++i) {
    if (range[i] == '(') ++depth;
    else if (range[i] == ')') --depth;
    else if (range[i] == ',' && depth == 0) {
      if (split != std::string::npos) fail("expected two values in { min, max }");
      split = i;
    }
  }
  if (split == std::string::npos) fail("expected two values in { min, max }");
  t.lo_text = range.substr(0, split);
  t.hi_text = range.substr(split + 1);
  rest = trim(rest.substr(close + 1));
}

UniformTail read_tail(std::string rest, const LineError& fail) {
  UniformTail t;
  rest = trim(rest);
  if (!rest.empty() && rest[0] == '=') {
    rest = trim(rest.substr(1));
    // The value: a number up to the next blank, or a constructor up to its ')'.
    size_t end = 0;
    if (!rest.empty() && std::isalpha(static_cast<unsigned char>(rest[0]))) {
      end = rest.find(')');
      end = end == std::string::npos ? rest.size() : end + 1;
    } else {
      while (end < rest.size() && !std::isspace(static_cast<unsigned char>(rest[end])) && rest[end] != '{') ++end;
    }
    t.def = trim(rest.substr(0, end));
    rest = trim(rest.substr(end));
  }
  if (rest.rfind("in", 0) == 0) read_range(rest, t, fail);
  if (!rest.empty() && rest.rfind("step", 0) != 0 && rest.rfind("sequ", 0) != 0)
    fail("unexpected '" + rest + "'");
  // `step` and `sequencer` tune the extension's own panel; marchstudio's slider is continuous.
  return t;
}

// The type's components, and whether it is an int or a colour.
int type_components(const std::string& type, bool& is_int, bool& color, const LineError& fail) {
  if (type == "float") return 1;
  if (type == "int") return is_int = true, 1;
  if (type == "vec2" || type == "vec3" || type == "vec4") return type.back() - '0';
  if (type == "color3") return color = true, 3;
  if (type.rfind("ivec", 0) == 0)
    fail("'" + type + "': marchstudio's uniforms are float, int, vec2, vec3 and vec4", "declare it as vec" + type.substr(4));
  fail("'" + type + "' is not a type #iUniform takes", "float, int, vec2, vec3, vec4 or color3");
}

}  // namespace

std::string vscode_uniform_line(const std::string& args, const std::string& where, int line) {
  const LineError fail{where, line};
  std::istringstream in(args);
  std::string type, name;
  in >> type >> name;
  const size_t eq_name = name.find('=');
  std::string rest;
  std::getline(in, rest);
  if (eq_name != std::string::npos) rest = name.substr(eq_name) + rest, name = name.substr(0, eq_name);
  if (type.empty() || name.empty()) fail("expected a type and a name");
  bool is_int = false, color = false;
  const int components = type_components(type, is_int, color, fail);
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') fail("'" + name + "' is not a GLSL name");
  const UniformTail t = read_tail(rest, fail);
  const std::string& def = t.def;

  std::vector<double> value;
  if (!def.empty() && (!parse_value(def, value) || (value.size() != 1 && static_cast<int>(value.size()) != components)))
    fail("'" + def + "' is not a value of type " + type);
  double lo = 0, hi = 1;
  const bool ranged = !t.lo_text.empty();
  if (ranged) {
    std::vector<double> l, h;
    if (!parse_value(t.lo_text, l) || !parse_value(t.hi_text, h))
      fail("the range { " + trim(t.lo_text) + ", " + trim(t.hi_text) + " } is not two values");
    for (const std::vector<double>* v : {&l, &h})
      for (double x : *v)
        if (x != (*v)[0])
          fail("a range that differs per component: marchstudio's sliders share one range", "give one number for min and max");
    lo = l[0];
    hi = h[0];
    if (!(lo < hi)) fail("the range's minimum must be below its maximum");
    if (value.empty()) value = {lo};  // as the extension: no default, the minimum
  }
  if (value.empty()) fail("no value: give '= value' or a range 'in { min, max }'");
  if (is_int) {
    for (double v : value)
      if (v != std::floor(v)) fail("'" + def + "' is not an int");
    // Past int's range the literal would wrap or not compile.
    for (double v : {value[0], lo, hi})
      if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
        fail(format_int_range(v), "#iUniform int is a 32-bit GLSL int");
  }

  const std::string glsl_type = color ? "vec3" : type;
  std::string init;
  if (components == 1) {
    init = number(value[0], is_int);
  } else {
    init = glsl_type + "(";
    for (size_t i = 0; i < value.size(); ++i) init += (i ? ", " : "") + number(value[i], false);
    init += ")";
  }
  std::string out = "uniform " + glsl_type + " " + name + " = " + init + ";";
  if (color) out += " // color";
  else if (ranged) out += " // range(" + number(lo, is_int) + ", " + number(hi, is_int) + ")";
  return out;
}

}  // namespace ms
