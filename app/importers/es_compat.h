// Shadertoy's code is GLSL ES 3.00 (WebGL2); marchstudio compiles it as
// #version 450 core. Words that ES leaves free but desktop GLSL 4.50 takes
// as keywords (`buffer`, `shared`, `precise`, `sample`, `patch`,
// `subroutine`, ...) would fail to compile, so they are renamed, token by
// token outside comments and quotes, keeping every line where it was: a
// compile error still points at the user's line.
//
//   std::string gl = rename_desktop_keywords("float sample = 1.0;");
//   // "float ms_es_sample = 1.0;"
#pragma once
#include <string>
#include <string_view>

namespace ms {

// The words renamed, and the prefix they get.
inline constexpr std::string_view kEsRenamePrefix = "ms_es_";
bool is_desktop_only_keyword(std::string_view word);

std::string rename_desktop_keywords(std::string_view code);

}  // namespace ms
