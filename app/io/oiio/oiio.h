// The image module's insides (io/image_backend.h): every OpenImageIO call
// marchstudio makes. Built into marchstudio-oiio.so only; the executable
// reaches these through ImageBackend, never by linking them.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/image_backend.h"
#include "io/image_stream.h"

namespace ms::oiio {

// libpng's default error handler prints "libpng error: ..." on stderr
// before OpenImageIO hands us the same text, which we print as our one
// line. For the scope's life fd 2 is captured; at its end the rest of what
// came (another thread's warning) goes on to stderr, libpng's lines not.
class LibpngLines {
 public:
  LibpngLines();
  ~LibpngLines();
  LibpngLines(const LibpngLines&) = delete;
  LibpngLines& operator=(const LibpngLines&) = delete;
};

// stream.cpp
void write(const Image& image, const std::filesystem::path& path, ImageFormat format, const ImageMetadata& meta);
std::unique_ptr<ImageRowWriter> open_rows(const std::filesystem::path& path, ImageFormat format, int width, int height,
                                          const std::vector<std::string>& channels, const ImageMetadata& meta);

// codec.cpp
ImageInfo read_info(const std::string& bytes, const std::filesystem::path& name);
Image read(const std::string& bytes, const std::filesystem::path& name, bool straight_alpha);
std::string decode_problem(const std::string& bytes, const std::filesystem::path& name);
Image quantize_8bit(const Image& image);

// compare.cpp
CompareMetrics compare(const Image& a, const Image& b, const CompareOptions& opts);
Image diff_heatmap(const Image& a, const Image& b, float scale);

// canvas.cpp
std::unique_ptr<ImageCanvas> canvas(int width, int height, const ImageCanvas::Color& background);

}  // namespace ms::oiio
