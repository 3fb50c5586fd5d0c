// The value of a `#if` / `#elif` expression, as the driver's preprocessor
// computes it: C's integer arithmetic on macro-expanded tokens, `defined`
// already replaced by 0 or 1. On desktop GLSL an identifier left after
// expansion is 0 (checked on Mesa 22.3: `#if UNDEFINED == 0` is taken).
// Identifiers the caller cannot know (a driver's GL_<extension> macros)
// make the result unknown.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "preprocess/pp_token.h"

namespace ms {

struct PpValue {
  bool known = true;
  std::int64_t value = 0;
  std::string error;  // not empty: the expression is malformed (the driver fails it too)
};

// `unknown(name)`: whether an identifier left after expansion has a value
// only the driver knows.
PpValue eval_pp_expression(const std::vector<PpToken>& tokens,
                           const std::function<bool(std::string_view)>& unknown);

}  // namespace ms
