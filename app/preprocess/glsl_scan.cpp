#include "preprocess/glsl_scan.h"

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

std::string definition_type(std::string_view code, std::string_view name) {
  static constexpr std::string_view kTypes[] = {"void",  "float", "int",   "uint",  "bool",  "double", "vec2",
                                                "vec3",  "vec4",  "ivec2", "ivec3", "ivec4", "uvec2",  "uvec3",
                                                "uvec4", "bvec2", "bvec3", "bvec4", "mat2",  "mat3",   "mat4"};
  size_t best = std::string_view::npos;
  std::string_view type;
  for (std::string_view t : kTypes)
    if (const size_t at = find_definition(code, name, t); at < best) best = at, type = t;
  return std::string(type);
}

std::string comment_label(std::string_view label) {
  std::string out;
  for (char c : label) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) c = ' ';
    if (c == '\\') c = '/';
    if (c == '/' && !out.empty() && out.back() == '*') out += ' ';
    out += c;
  }
  return out;
}

std::string define_value_problem(std::string_view value) {
  if (value.find_first_of("\r\n") != std::string_view::npos) return "spans lines";
  const size_t last = value.find_last_not_of(" \t");
  if (last != std::string_view::npos && value[last] == '\\')
    return "ends in a backslash, which would join the next line of the shader";
  return {};
}

}  // namespace ms
