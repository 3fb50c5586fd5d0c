// Checks on raw TOML text before toml++ sees it, for limits the library
// itself does not enforce. toml++ 3.3 recurses once per component of a
// dotted key (`[a.b.c]`, `a.b.c = 1`): a key of ~50 000 components
// overflowed the stack (a long fuzz_scene input), in Debian's shared
// library where we cannot fix it.
#pragma once
#include <string>
#include <string_view>

namespace ms {

inline constexpr int kMaxTomlKeyDepth = 64;

// Throws bad_input at `file`:line when a key has more than
// kMaxTomlKeyDepth dotted components. Strings and comments are skipped; a
// value never has more than one '.' between separators, so only keys can
// trip it.
void check_toml_key_depth(std::string_view text, const std::string& file);

}  // namespace ms
