#include "preprocess/log_map.h"

#include <cctype>
#include <regex>
#include <set>

#include "core/suggest.h"
#include "preprocess/glsl_scan.h"

namespace ms {

namespace {

// A NUL is blank too: a log read with its terminator ends in one.
std::string trimmed(std::string_view s) {
  constexpr std::string_view blank(" \t\r\0", 4);
  size_t b = s.find_first_not_of(blank);
  if (b == std::string_view::npos) return {};
  size_t e = s.find_last_not_of(blank);
  return std::string(s.substr(b, e - b + 1));
}

// Drivers spell severities differently ("preprocessor error", "ERROR",
// "fatal error"); callers only need error / warning / info.
std::string normalise_severity(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s.find("error") != std::string::npos) return "error";
  if (s.find("warning") != std::string::npos) return "warning";
  return "info";
}

// glslang prefixes messages with the offending token: `'' :  syntax error`.
std::string clean_message(std::string m) {
  if (m.rfind("'' :", 0) == 0) m = m.substr(4);
  return trimmed(m);
}

void locate(ShaderDiagnostic& d, const ShaderSource& src, const std::string& string_no, const std::string& line) {
  SourceLocation loc = map_location(src, std::stoll(string_no), std::stoll(line));
  if (loc.file.empty()) {
    // Numbers we did not emit keep their raw location rather than pointing at a wrong file.
    d.message = string_no + ":" + line + ": " + d.message;
  } else {
    d.file = std::move(loc.file);
    d.line = loc.line;
  }
}

// The name a driver reports unknown, in Mesa's, glslang's and NVIDIA's
// words, or "".
std::string unknown_name(const std::string& m) {
  static const std::regex forms[] = {
      std::regex(R"(^`([A-Za-z_]\w*)' undeclared)"),                     // Mesa
      std::regex(R"(^no function with name '([A-Za-z_]\w*)')"),          // Mesa
      std::regex(R"(^'([A-Za-z_]\w*)' : (?:undeclared identifier|no matching overloaded function found))"),  // glslang
      std::regex(R"(undefined variable \"([A-Za-z_]\w*)\")"),             // NVIDIA
  };
  if (m.size() > 300) return {};  // no such message is long; the regex recurses per character
  std::smatch hit;
  for (const std::regex& f : forms)
    if (std::regex_search(m, hit, f)) return hit[1];
  return {};
}

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The names `program` defines: each #define's, and each function's (an
// identifier after a type and before '(').
std::vector<std::string> defined_names(std::string_view program) {
  static const std::set<std::string, std::less<>> not_types = {"return", "else", "case", "define", "if", "elif",
                                                               "ifdef", "ifndef", "undef", "defined"};
  const std::string code = strip_comments(program);
  std::set<std::string> names;
  std::string previous;  // the identifier just before, with only blanks between
  bool after_hash_define = false;
  for (size_t i = 0; i < code.size();) {
    const char c = code[i];
    if (std::isdigit(static_cast<unsigned char>(c))) {  // a number, with its suffix or exponent (1.0e5, 0x1Fu)
      while (i < code.size() && (ident_char(code[i]) || code[i] == '.')) ++i;
      previous.clear();
      continue;
    }
    if (!ident_char(c)) {
      if (c == '#') {
        const size_t j = code.find_first_not_of(" \t", i + 1);
        after_hash_define = j != std::string::npos && code.compare(j, 6, "define") == 0;
      }
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') previous.clear();
      ++i;
      continue;
    }
    size_t j = i;
    while (j < code.size() && ident_char(code[j])) ++j;
    std::string word = code.substr(i, j - i);
    const size_t next = code.find_first_not_of(" \t\n", j);
    if (after_hash_define && word != "define") {
      names.insert(word);
      after_hash_define = false;
    } else if (next != std::string::npos && code[next] == '(' && !previous.empty() && !not_types.count(previous)) {
      names.insert(word);
    }
    previous = std::move(word);
    i = j;
  }
  return {names.begin(), names.end()};
}

}  // namespace

void suggest_names(std::vector<ShaderDiagnostic>& diags, std::string_view program) {
  static const std::vector<std::string> builtins = {
      "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "pow", "exp", "log",
      "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "trunc", "round", "ceil", "fract", "mod", "modf",
      "min", "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "length", "distance", "dot", "cross",
      "normalize", "reflect", "refract", "faceforward", "transpose", "inverse", "determinant", "texture", "texelFetch",
      "textureLod", "textureSize", "dFdx", "dFdy", "fwidth", "vec2", "vec3", "vec4", "mat2", "mat3", "mat4"};
  std::vector<std::string> names;
  std::vector<std::string_view> candidates;
  for (ShaderDiagnostic& d : diags) {
    const std::string name = d.severity == "error" ? unknown_name(d.message) : std::string();
    if (name.empty()) continue;
    if (names.empty()) {  // read the program once, and only when a name is unknown
      names = defined_names(program);
      names.insert(names.end(), builtins.begin(), builtins.end());
    }
    candidates.clear();
    for (const std::string& n : names)
      if (n != name) candidates.emplace_back(n);
    d.suggestion = did_you_mean(name, candidates);
  }
}

SourceLocation map_location(const ShaderSource& src, long long string_no, long long line) {
  // Lines of included files carry their file in the line number (see
  // kLineStride); the string number is only a fallback, since Mesa reports 0
  // for most errors.
  if (line >= kLineStride) {
    const long long file = line / kLineStride;
    if (file < static_cast<long long>(src.files.size()))
      return {src.files[static_cast<size_t>(file)], static_cast<int>(line % kLineStride)};
    return {};
  }
  if (string_no >= 0 && string_no < static_cast<long long>(src.files.size()) && line > 0)
    return {src.files[static_cast<size_t>(string_no)], static_cast<int>(line)};
  return {};
}

std::vector<ShaderDiagnostic> parse_info_log(std::string_view log, const ShaderSource& src) {
  static const std::regex mesa(R"(^(\d{1,10}):(\d{1,10})\(\d+\):\s*([A-Za-z ]*?)\s*:\s*(.*)$)");
  static const std::regex nvidia(R"(^(\d{1,10})\((\d{1,10})\)\s*:\s*(fatal error|error|warning)\s*(?:[A-Z]+\d+)?\s*:\s*(.*)$)");
  static const std::regex glslang(R"(^(ERROR|WARNING|INFO|NOTE|UNIMPLEMENTED):\s*(\d{1,10}):(\d{1,10}):\s*(.*)$)");
  static const std::regex bare(R"(^(ERROR|WARNING|error|warning|fatal error):\s*(.*)$)");
  static const std::regex summary(R"(^\d+ compilation errors\..*$)");

  std::vector<ShaderDiagnostic> out;
  size_t pos = 0;
  while (pos <= log.size()) {
    size_t nl = log.find('\n', pos);
    size_t end = nl == std::string_view::npos ? log.size() : nl;
    std::string line = trimmed(log.substr(pos, end - pos));
    pos = end + 1;
    if (line.empty()) continue;
    // libstdc++'s regex recurses once per character: a 60 KB line (a driver
    // quoting a huge token) overflowed the stack (a long fuzz_preprocess
    // input). The location is at the start; the rest is message.
    constexpr size_t kMaxLine = 2000;
    if (line.size() > kMaxLine) line = line.substr(0, kMaxLine) + "...";

    std::smatch m;
    ShaderDiagnostic d;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia)) {
      d.severity = normalise_severity(m[3]);
      d.message = clean_message(m[4]);
      locate(d, src, m[1], m[2]);
    } else if (std::regex_match(line, m, glslang)) {
      d.severity = normalise_severity(m[1]);
      d.message = clean_message(m[4]);
      locate(d, src, m[2], m[3]);
    } else if (std::regex_match(line, m, bare)) {
      std::string rest = m[2];
      if (std::regex_match(rest, summary)) continue;
      d.severity = normalise_severity(m[1]);
      d.message = clean_message(rest);
    } else {
      d.message = line;
    }
    out.push_back(std::move(d));
  }
  return out;
}

std::string format_diagnostics(const std::vector<ShaderDiagnostic>& diags) {
  std::string out;
  for (const auto& d : diags) {
    if (!d.file.empty()) {
      out += d.file;
      if (d.line > 0) {
        out += ':';
        out += std::to_string(d.line);
      }
      out += ": ";
    }
    if (!d.severity.empty()) out += d.severity + ": ";
    out += d.message + (d.suggestion.empty() ? "" : " (" + d.suggestion + ")") + "\n";
  }
  return out;
}

}  // namespace ms
