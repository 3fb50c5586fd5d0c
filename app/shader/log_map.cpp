#include "shader/log_map.h"

#include <cctype>
#include <regex>

namespace ms {

namespace {

std::string trimmed(std::string_view s) {
  size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  size_t e = s.find_last_not_of(" \t\r");
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

}  // namespace

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
    out += d.message + "\n";
  }
  return out;
}

}  // namespace ms
