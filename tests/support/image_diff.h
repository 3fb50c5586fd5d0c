// Image comparisons for the dispatch tests (test_dispatch*.cpp): the largest
// difference in any channel, and one channel's values.
//
//   EXPECT_LE(max_diff(fragment, compute), 1.0 / 255 + 1e-6);
//   EXPECT_EQ(channel(f, "steps"), channel(c, "steps"));
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/image.h"

namespace ms::test {

// Largest |a - b| over every channel; infinity when the shapes, channel
// names or NaN positions differ, or the images are empty.
inline double max_diff(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.pixels.size() != b.pixels.size() ||
      a.pixels.empty())
    return INFINITY;
  double m = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const float x = a.pixels[i], y = b.pixels[i];
    if (std::isnan(x) != std::isnan(y)) return INFINITY;
    if (!std::isnan(x)) m = std::max(m, static_cast<double>(std::fabs(x - y)));
  }
  return m;
}

// Channel `name`'s values, pixel by pixel; empty when there is none.
inline std::vector<float> channel(const Image& img, const std::string& name) {
  std::vector<float> out;
  const auto it = std::find(img.channels.begin(), img.channels.end(), name);
  if (it == img.channels.end()) return out;
  const size_t c = static_cast<size_t>(it - img.channels.begin()), n = img.channels.size();
  for (size_t i = c; i < img.pixels.size(); i += n) out.push_back(img.pixels[i]);
  return out;
}

}  // namespace ms::test
