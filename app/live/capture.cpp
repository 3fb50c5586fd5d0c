#include "live/capture.h"

#include <cstring>
#include <string>

#include "gl/gl.h"

namespace ms::live {
namespace fs = std::filesystem;

Image grab_window(int w, int h) {
  Image img;
  img.width = w;
  img.height = h;
  img.channels = {"R", "G", "B"};
  std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  img.pixels.resize(rgb.size());
  // GL's first row is the bottom one; images are stored top row first. The
  // bytes are display values already: write_image stores them unchanged.
  for (int y = 0; y < h; ++y) {
    const unsigned char* src = rgb.data() + static_cast<size_t>(h - 1 - y) * w * 3;
    float* dst = img.pixels.data() + static_cast<size_t>(y) * w * 3;
    for (int i = 0; i < w * 3; ++i) dst[i] = static_cast<float>(src[i]) / 255.0f;
  }
  return img;
}

fs::path next_free_path(const fs::path& dir, const std::string& stem) {
  std::error_code ec;
  fs::create_directories(dir, ec);  // a failure shows up when the file is written
  for (int n = 1;; ++n) {
    fs::path p = dir / (stem + "_" + std::to_string(n) + ".png");
    if (!fs::exists(p, ec)) return p;
  }
}

}  // namespace ms::live
