// The NaN/Inf guard: render's stills and tiles, sequences and bench count
// a frame's pixels with NaN or Inf in any channel here, mesh the samples of
// the field, and warn (or with --strict fail) in one message.
//
//   guard_nonfinite({input, strict, "", "nothing written"}, count, pixels); // warns, or throws with strict
#pragma once
#include <string>

#include "io/image.h"

namespace ms {

// Pixels of `a` (and of `b`, same size, when given) with a NaN or Inf in
// any channel (docs/stability.md).
long long count_nonfinite_pixels(const Image& a, const Image* b = nullptr);

struct NonfiniteGuard {
  std::string input;        // named at the start of the line
  bool strict = false;      // any such pixel is an error (exit 1)
  std::string where;        // "frame 12", or empty: a still
  std::string consequence;  // after "; " in the error: "nothing written"; empty: none
  std::string unit = "pixels";  // what is counted: a mesh's are "samples of map()"
};

// "N of M <unit> have NaN/Inf values" on stderr as a warning, or with
// g.strict thrown as an Error (exit 1, key --strict); nothing for 0.
void guard_nonfinite(const NonfiniteGuard& g, long long nonfinite, long long pixels);
}  // namespace ms
