// The module's one export: the ImageBackend that io/image_backend.cpp
// finds with dlsym.
#include "io/oiio/oiio.h"

namespace ms::oiio {
namespace {

class OiioBackend final : public ImageBackend {
 public:
  void write(const Image& image, const std::filesystem::path& path, ImageFormat format,
             const ImageMetadata& meta) const override {
    oiio::write(image, path, format, meta);
  }
  std::unique_ptr<ImageRowWriter> open_rows(const std::filesystem::path& path, ImageFormat format, int width,
                                            int height, const std::vector<std::string>& channels,
                                            const ImageMetadata& meta) const override {
    return oiio::open_rows(path, format, width, height, channels, meta);
  }
  ImageInfo read_info(const std::string& bytes, const std::filesystem::path& name) const override {
    const LibpngLines quiet;
    return oiio::read_info(bytes, name);
  }
  Image read(const std::string& bytes, const std::filesystem::path& name, bool straight_alpha) const override {
    const LibpngLines quiet;
    return oiio::read(bytes, name, straight_alpha);
  }
  std::string decode_problem(const std::string& bytes, const std::filesystem::path& name) const override {
    const LibpngLines quiet;
    return oiio::decode_problem(bytes, name);
  }
  Image quantize_8bit(const Image& image) const override { return oiio::quantize_8bit(image); }
  CompareMetrics compare(const Image& a, const Image& b, const CompareOptions& opts) const override {
    return oiio::compare(a, b, opts);
  }
  Image diff_heatmap(const Image& a, const Image& b, float scale) const override {
    return oiio::diff_heatmap(a, b, scale);
  }
  std::unique_ptr<ImageCanvas> canvas(int width, int height, const ImageCanvas::Color& background) const override {
    return oiio::canvas(width, height, background);
  }
};

}  // namespace
}  // namespace ms::oiio

extern "C" __attribute__((visibility("default"))) const ms::ImageBackend* marchstudio_image_backend() {
  static const ms::oiio::OiioBackend backend;
  return &backend;
}
