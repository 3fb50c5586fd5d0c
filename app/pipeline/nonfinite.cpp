#include "pipeline/nonfinite.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"

namespace ms {

long long count_nonfinite_pixels(const Image& a, const Image* b) {
  const size_t n = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  auto bad = [](const Image& img, size_t p) {
    const size_t c = img.channels.size();
    for (size_t i = 0; i < c; ++i)
      if (!std::isfinite(img.pixels[p * c + i])) return true;
    return false;
  };
  long long count = 0;
  for (size_t p = 0; p < n; ++p) count += bad(a, p) || (b && !b->pixels.empty() && bad(*b, p));
  return count;
}

void guard_nonfinite(const NonfiniteGuard& g, long long nonfinite, long long pixels) {
  if (nonfinite <= 0) return;
  const std::string what = (g.where.empty() ? "" : g.where + ": ") + std::to_string(nonfinite) + " of " +
                           std::to_string(pixels) + " " + g.unit + " have NaN/Inf values";
  if (g.strict)
    throw Error({Exit::threshold, g.input, 0, "--strict", g.consequence.empty() ? what : what + "; " + g.consequence,
                 {}, {}});
  std::fprintf(stderr, "marchstudio: %s: warning: %s (--strict makes this an error)\n", g.input.c_str(), what.c_str());
}

}  // namespace ms
