#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "io/oiio/oiio.h"

namespace ms::oiio {
namespace {

namespace IBA = OIIO::ImageBufAlgo;

// The first font that OpenImageIO can rasterise: DejaVu Sans by path (Debian's
// fonts-dejavu-core), by name, then OIIO's default. Empty when none works;
// " " stands for OIIO's default.
std::string find_font() {
  for (const char* f : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "DejaVuSans", ""})
    if (IBA::text_size("Ag", 14, f).defined()) return f[0] ? f : " ";
  return {};
}

class BufCanvas final : public ImageCanvas {
 public:
  BufCanvas(int width, int height, const Color& background)
      : buf_(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT)), font_(find_font()) {
    IBA::fill(buf_, background);
  }
  void line(int x1, int y1, int x2, int y2, const Color& c) override { IBA::render_line(buf_, x1, y1, x2, y2, c); }
  void box(int x1, int y1, int x2, int y2, const Color& c, bool fill) override {
    IBA::render_box(buf_, x1, y1, x2, y2, c, fill);
  }
  void text(int x, int y, const std::string& s, int size, const Color& c, AlignX ax, AlignY ay) override {
    if (font_.empty()) return;
    const auto oax = ax == AlignX::right    ? IBA::TextAlignX::Right
                     : ax == AlignX::center ? IBA::TextAlignX::Center
                                            : IBA::TextAlignX::Left;
    const auto oay = ay == AlignY::top      ? IBA::TextAlignY::Top
                     : ay == AlignY::bottom ? IBA::TextAlignY::Bottom
                     : ay == AlignY::center ? IBA::TextAlignY::Center
                                            : IBA::TextAlignY::Baseline;
    IBA::render_text(buf_, x, y, s, size, font_ == " " ? "" : font_, c, oax, oay);
  }
  bool has_text() const override { return !font_.empty(); }
  Image pixels() const override {
    const OIIO::ImageSpec& s = buf_.spec();
    Image out;
    out.width = s.width;
    out.height = s.height;
    out.channels = {"R", "G", "B"};
    out.pixels.resize(static_cast<size_t>(s.width) * s.height * 3);
    buf_.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out.pixels.data());
    return out;
  }

 private:
  OIIO::ImageBuf buf_;
  std::string font_;
};

}  // namespace

std::unique_ptr<ImageCanvas> canvas(int width, int height, const ImageCanvas::Color& background) {
  return std::make_unique<BufCanvas>(width, height, background);
}

}  // namespace ms::oiio
