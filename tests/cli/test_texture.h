// Small textures the CLI tests write themselves, with known texels.
#pragma once
#include <array>
#include <filesystem>
#include <functional>

#include "io/image_io.h"

namespace ms::test {

// A 4x2 RGBA texture: texel (x, y), row 0 the file's top, is texel(x, y), alpha 1.
inline void write_texture_4x2(const std::filesystem::path& p, const std::function<std::array<float, 3>(int, int)>& texel) {
  Image t;
  t.width = 4;
  t.height = 2;
  t.channels = {"R", "G", "B", "A"};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      const std::array<float, 3> c = texel(x, y);
      t.pixels.insert(t.pixels.end(), {c[0], c[1], c[2], 1.0f});
    }
  write_image(t, p);
}

// Texels that all differ: red = 40 (x + 4 y) / 255, green = x / 3, blue = y.
inline void write_texture(const std::filesystem::path& p) {
  write_texture_4x2(p, [](int x, int y) {
    return std::array<float, 3>{40.0f * (x + 4 * y) / 255.0f, x / 3.0f, static_cast<float>(y)};
  });
}

}  // namespace ms::test
