#include "importers/es_compat.h"

#include <algorithm>
#include <array>

namespace ms {
namespace {

// Keywords of GLSL 4.50 (section 3.6) that are not keywords of GLSL ES
// 3.00: `buffer`, `shared` and `precise` are free names there; the rest
// ES only reserves, and browsers' compilers have let some through.
constexpr std::array<std::string_view, 18> kWords = {
    "buffer",   "shared",    "precise",       "sample",      "patch",    "subroutine", "coherent",  "volatile", "restrict",
    "readonly", "writeonly", "noperspective", "atomic_uint", "resource", "common",     "partition", "active",   "filter"};

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

}  // namespace

bool is_desktop_only_keyword(std::string_view word) {
  return std::find(kWords.begin(), kWords.end(), word) != kWords.end();
}

std::string rename_desktop_keywords(std::string_view s) {
  std::string out;
  out.reserve(s.size() + 64);
  size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {  // line comment: copied
      const size_t end = std::min(s.find('\n', i), s.size());
      out.append(s.substr(i, end - i));
      i = end;
    } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {  // block comment
      const size_t close = s.find("*/", i + 2);
      const size_t end = close == std::string_view::npos ? s.size() : close + 2;
      out.append(s.substr(i, end - i));
      i = end;
    } else if (c == '"') {  // an #include's name
      const size_t close = s.find_first_of("\"\n", i + 1);
      const size_t end = close == std::string_view::npos ? s.size() : close + (s[close] == '"' ? 1 : 0);
      out.append(s.substr(i, end - i));
      i = end;
    } else if (ident_start(c)) {
      size_t e = i + 1;
      while (e < s.size() && ident_char(s[e])) ++e;
      const std::string_view word = s.substr(i, e - i);
      if (is_desktop_only_keyword(word)) out.append(kEsRenamePrefix);
      out.append(word);
      i = e;
    } else if (c >= '0' && c <= '9') {  // a number's letters (1e5, 0x1f) are not words
      size_t e = i + 1;
      while (e < s.size() && (ident_char(s[e]) || s[e] == '.')) ++e;
      out.append(s.substr(i, e - i));
      i = e;
    } else {
      out.push_back(c);
      ++i;
    }
  }
  return out;
}

}  // namespace ms
