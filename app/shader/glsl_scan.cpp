#include "shader/glsl_scan.h"

#include <cctype>

namespace ms {

std::string strip_comments(std::string_view s) {
  std::string out(s);
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i] != '/' || i + 1 >= out.size()) continue;
    if (out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      for (i += 2; i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/'); ++i)
        if (out[i] != '\n') out[i] = ' ';
      if (i + 1 < out.size()) out[i] = out[i + 1] = ' ';
      ++i;
    }
  }
  return out;
}

// A shader with 50 KB of spaces after `void` once overflowed the stack
// through std::regex (a long fuzz_shadertoy input): hence the scan.
size_t find_definition(std::string_view code, std::string_view name, std::string_view type) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; };
  for (size_t at = code.find(type); at != std::string_view::npos; at = code.find(type, at + 1)) {
    if (at > 0 && word(code[at - 1])) continue;
    size_t i = at + type.size();
    const size_t gap = i;
    while (i < code.size() && space(code[i])) ++i;
    if (i == gap || code.substr(i, name.size()) != name) continue;
    i += name.size();
    while (i < code.size() && space(code[i])) ++i;
    if (i < code.size() && code[i] == '(') return at;
  }
  return std::string_view::npos;
}

}  // namespace ms
