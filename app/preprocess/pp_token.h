// Preprocessing tokens of GLSL, as the driver's preprocessor splits them
// (GLSL 4.60 section 3.3, which follows C's): identifiers, numbers,
// punctuators and single other characters. Used by preprocess/macro_engine.h,
// which models the driver's macro expansion; no GL here.
//
//   std::vector<PpToken> toks;
//   lex_pp_tokens("a += b##c", {}, toks);  // a, +=, b, ##, c
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

namespace ms {

enum class PpKind : std::uint8_t { identifier, number, punct, other };

// Where a token came from: the file index of ShaderSource::files and the
// line in it, for error messages.
struct PpWhere {
  int file = 0;
  int line = 0;
};

struct PpToken {
  std::string_view text;  // points into the source, a macro body or the engine's arena
  PpKind kind = PpKind::other;
  bool space_before = false;  // whitespace separated it from the previous token
  int hideset = 0;            // macro_expand.cpp: the macros this token may no longer expand
  PpWhere where;
};

// Appends the tokens of `text` (comments already removed) to `out`.
void lex_pp_tokens(std::string_view text, PpWhere where, std::vector<PpToken>& out);

// `t` is the punctuator `s`.
inline bool is_punct(const PpToken& t, std::string_view s) { return t.kind == PpKind::punct && t.text == s; }

inline bool is_pp_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool is_pp_ident_char(char c) { return is_pp_ident_start(c) || (c >= '0' && c <= '9'); }

}  // namespace ms
