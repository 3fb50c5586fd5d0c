#include "scene/toml_guard.h"

#include "core/error.h"

namespace ms {

void check_toml_key_depth(std::string_view text, const std::string& file) {
  int line = 1, dots = 0;
  const size_t n = text.size();
  for (size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      dots = 0;
    } else if (c == '#') {  // a comment runs to the end of the line
      while (i + 1 < n && text[i + 1] != '\n') ++i;
    } else if (c == '"' || c == '\'') {
      // Basic "..." (with escapes) or literal '...'; tripled: multi-line.
      const bool triple = i + 2 < n && text[i + 1] == c && text[i + 2] == c;
      const std::string_view close = triple ? std::string_view(text.data() + i, 3) : std::string_view(&text[i], 1);
      for (i += close.size(); i < n; ++i) {
        if (text[i] == '\n') ++line;
        if (c == '"' && text[i] == '\\') {
          if (i + 1 < n && text[i + 1] == '\n') ++line;
          ++i;
          continue;
        }
        if (text.compare(i, close.size(), close) == 0) {
          i += close.size() - 1;
          break;
        }
        if (!triple && text[i] == '\n') break;  // unterminated: toml++ reports it
      }
    } else if (c == '.') {
      if (++dots >= kMaxTomlKeyDepth)
        fail_input("a key nested more than " + std::to_string(kMaxTomlKeyDepth) + " levels deep", file, line, {},
                   "dotted keys like a.b.c nest tables; no scene key is that deep");
    } else if (c == '=' || c == ',' || c == '[' || c == ']' || c == '{' || c == '}') {
      dots = 0;
    }
  }
}

}  // namespace ms
