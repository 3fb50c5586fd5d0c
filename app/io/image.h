// Image: float pixels, top row first, interleaved channels. The hand-off
// between render/ (which produces it) and io/ (which writes it).
#pragma once
#include <string>
#include <vector>

namespace ms {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;  // e.g. {"R","G","B"}; EXR names (Z, N.x, ...) for AOVs
  std::vector<float> pixels;          // width * height * channels.size(), top row first

  int nchannels() const { return static_cast<int>(channels.size()); }
  float at(int x, int y, int c) const { return pixels[(static_cast<size_t>(y) * width + x) * nchannels() + c]; }
};

}  // namespace ms
