#include "preprocess/directive.h"

#include <cstdlib>

namespace ms {
namespace {
std::string_view trim(std::string_view s) {
  size_t b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace

// Classifies a line that does not start inside a block comment.
Directive parse_directive(std::string_view line) {
  Directive d;
  std::string_view s = trim(line);
  if (s.empty() || s[0] != '#') return d;
  s = trim(s.substr(1));
  size_t n = 0;
  while (n < s.size() && is_word_char(s[n])) ++n;
  std::string_view word = s.substr(0, n);
  std::string_view rest = trim(s.substr(n));
  d.kind = DirectiveKind::other;
  if (word == "version") {
    d.kind = DirectiveKind::version;
  } else if (word == "line") {
    d.kind = DirectiveKind::line;
    char* end = nullptr;
    const std::string num(rest.substr(0, rest.find_first_of(" \t")));
    d.line = std::strtol(num.c_str(), &end, 10);
    if (num.empty() || *end != '\0' || d.line < 0) d.problem = "expected #line NUMBER";
  } else if (word == "else" || word == "elif" || word == "endif") {
    d.kind = DirectiveKind::group_switch;
  } else if (word == "pragma") {
    if (rest.substr(0, 4) == "once" && (rest.size() == 4 || !is_word_char(rest[4]))) d.kind = DirectiveKind::pragma_once;
  } else if (word == "include") {
    d.kind = DirectiveKind::include;
    if (rest.empty() || (rest[0] != '"' && rest[0] != '<')) {
      d.problem = "expected #include \"file\" or #include <file>";
      return d;
    }
    d.angled = rest[0] == '<';
    size_t close = rest.find(d.angled ? '>' : '"', 1);
    if (close == std::string_view::npos) {
      d.problem = "unterminated file name in #include";
      return d;
    }
    d.target = std::string(rest.substr(1, close - 1));
    std::string_view tail = trim(rest.substr(close + 1));
    if (d.target.empty()) d.problem = "empty file name in #include";
    else if (!tail.empty() && tail.substr(0, 2) != "//")
      d.problem = "unexpected text after #include: '" + std::string(tail) + "'";
  }
  return d;
}

// Updates the block-comment state over one line (GLSL has no string
// literals, so "/*" can only start a comment).
bool ends_in_comment(std::string_view line, bool in_comment) {
  for (size_t i = 0; i < line.size(); ++i) {
    if (in_comment) {
      if (line[i] == '*' && i + 1 < line.size() && line[i + 1] == '/') { in_comment = false; ++i; }
    } else if (line[i] == '/' && i + 1 < line.size()) {
      if (line[i + 1] == '/') return false;
      if (line[i + 1] == '*') { in_comment = true; ++i; }
    }
  }
  return in_comment;
}

bool is_blank_or_comment(std::string_view line, bool starts_in_comment) {
  bool c = starts_in_comment;
  for (size_t i = 0; i < line.size(); ++i) {
    if (c) {
      if (line[i] == '*' && i + 1 < line.size() && line[i + 1] == '/') { c = false; ++i; }
    } else if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '/') {
      return true;
    } else if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '*') {
      c = true; ++i;
    } else if (line[i] != ' ' && line[i] != '\t') {
      return false;
    }
  }
  return true;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    size_t end = nl == std::string_view::npos ? text.size() : nl;
    std::string_view l = text.substr(pos, end - pos);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines.push_back(l);
    pos = end + 1;
  }
  return lines;
}

std::vector<std::string> line_strings(std::string_view text) {
  std::vector<std::string> out(1);
  for (char c : text) {
    if (c == '\n') out.emplace_back();
    else out.back().push_back(c);
  }
  return out;
}

std::string include_guard(std::string_view text) {
  const std::vector<std::string_view> lines = split_lines(text);
  bool in_comment = false;
  std::string guard;
  int depth = 0;
  bool closed = false;  // the guard's #endif was seen: only comments may follow
  for (std::string_view line : lines) {
    const bool starts = in_comment;
    in_comment = ends_in_comment(line, in_comment);
    if (is_blank_or_comment(line, starts)) continue;
    if (closed) return {};
    std::string_view s = trim(line);
    if (starts || s.empty() || s[0] != '#') {
      if (guard.empty()) return {};
      continue;
    }
    s = trim(s.substr(1));
    size_t n = 0;
    while (n < s.size() && is_word_char(s[n])) ++n;
    const std::string_view word = s.substr(0, n);
    std::string_view rest = trim(s.substr(n));
    if (guard.empty()) {
      // #ifndef G, #if !defined G, #if !defined(G)
      if (word == "if" && rest.substr(0, 1) == "!") {
        rest = trim(rest.substr(1));
        if (rest.substr(0, 7) != "defined") return {};
        rest = trim(rest.substr(7));
        if (!rest.empty() && rest[0] == '(') rest = trim(rest.substr(1));
      } else if (word != "ifndef") {
        return {};
      }
      size_t e = 0;
      while (e < rest.size() && is_word_char(rest[e])) ++e;
      if (e == 0) return {};
      guard = std::string(rest.substr(0, e));
      depth = 1;
      continue;
    }
    if (word == "if" || word == "ifdef" || word == "ifndef") ++depth;
    else if ((word == "else" || word == "elif") && depth == 1) return {};  // code outside the guard
    else if (word == "endif" && --depth == 0) closed = true;
  }
  return closed ? guard : std::string{};
}

}  // namespace ms
