#include "preprocess/pp_token.h"

namespace ms {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The longest punctuator starting at s[0], longest first.
size_t punct_length(std::string_view s) {
  static constexpr std::string_view three[] = {"<<=", ">>="};
  static constexpr std::string_view two[] = {"++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||",
                                             "^^", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "##"};
  for (std::string_view p : three)
    if (s.substr(0, 3) == p) return 3;
  for (std::string_view p : two)
    if (s.substr(0, 2) == p) return 2;
  return 1;
}

bool is_punct_char(char c) {
  switch (c) {
    case '+': case '-': case '*': case '/': case '%': case '<': case '>': case '=': case '!':
    case '&': case '|': case '^': case '~': case '?': case ':': case ';': case ',': case '.':
    case '(': case ')': case '[': case ']': case '{': case '}': case '#':
      return true;
    default:
      return false;
  }
}

}  // namespace

void lex_pp_tokens(std::string_view s, PpWhere where, std::vector<PpToken>& out) {
  bool space = false;
  size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\n') {
      space = true;
      ++i;
      continue;
    }
    PpToken t;
    t.where = where;
    t.space_before = space;
    space = false;
    const size_t start = i;
    if (is_pp_ident_start(c)) {
      while (i < s.size() && is_pp_ident_char(s[i])) ++i;
      t.kind = PpKind::identifier;
    } else if (is_digit(c) || (c == '.' && i + 1 < s.size() && is_digit(s[i + 1]))) {
      // A pp-number: digits, letters, '_', '.', and a sign after an exponent.
      ++i;
      while (i < s.size()) {
        const char d = s[i];
        if ((d == '+' || d == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E')) ++i;
        else if (is_pp_ident_char(d) || d == '.') ++i;
        else break;
      }
      t.kind = PpKind::number;
    } else if (is_punct_char(c)) {
      i += punct_length(s.substr(i));
      t.kind = PpKind::punct;
    } else {
      ++i;
      t.kind = PpKind::other;
    }
    t.text = s.substr(start, i - start);
    out.push_back(t);
  }
}

}  // namespace ms
