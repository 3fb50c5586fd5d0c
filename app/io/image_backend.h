// Everything that needs OpenImageIO, behind one interface. The library and
// its ~260 dependencies (OpenCV, ffmpeg, GDAL...) take about 0.25 s to load,
// so they are not linked into marchstudio: io/oiio/ is a module
// (marchstudio-oiio.so) that is dlopen'd on demand. `render` and the
// viewer start that on a background thread once their GL context exists
// (the driver is dlopen'd too, and the dynamic loader runs one load at a
// time), so it overlaps the compile and the frame. --version and --help
// never load it (docs/performance.md#start-up).
//
//   preload_image_backend();                 // returns at once
//   image_backend().write(img, path, meta);  // waits for the load if needed
//
// The callers are io/image_io.cpp, io/image_stream.cpp, io/stored_pixels.cpp,
// io/sequence.cpp, io/compare.cpp and sweep/plot.cpp; nothing else calls
// the backend, and nothing but io/oiio/ includes an OpenImageIO header.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <array>
#include <memory>

#include "io/compare.h"
#include "io/image.h"
#include "io/image_io.h"
#include "io/image_stream.h"

namespace ms {

// An RGB float picture to draw on (sweep/plot.cpp's sweep plot), drawn
// with OpenImageIO's ImageBufAlgo. Coordinates in pixels, top row 0.
class ImageCanvas {
 public:
  using Color = std::array<float, 3>;
  enum class AlignX { left, right, center };
  enum class AlignY { baseline, top, bottom, center };
  virtual ~ImageCanvas() = default;
  virtual void line(int x1, int y1, int x2, int y2, const Color& c) = 0;
  virtual void box(int x1, int y1, int x2, int y2, const Color& c, bool fill) = 0;
  // Nothing when no font was found (has_text()).
  virtual void text(int x, int y, const std::string& s, int size, const Color& c, AlignX ax, AlignY ay) = 0;
  virtual bool has_text() const = 0;
  virtual Image pixels() const = 0;
};

class ImageBackend {
 public:
  virtual ~ImageBackend() = default;
  // write_image() after its checks: encode and commit through io/atomic_file.h.
  virtual void write(const Image& image, const std::filesystem::path& path, ImageFormat format,
                     const ImageMetadata& meta) const = 0;
  // ImageStreamWriter's insides (io/image_stream.h): the temporary opened
  // with the header written; rows then go through the codec's scanline writes.
  virtual std::unique_ptr<ImageRowWriter> open_rows(const std::filesystem::path& path, ImageFormat format, int width,
                                                    int height, const std::vector<std::string>& channels,
                                                    const ImageMetadata& meta) const = 0;
  // From a file's bytes (`name` picks the codec and names errors). Throw
  // bad_input naming `name`. The info's fingerprint is left empty.
  virtual ImageInfo read_info(const std::string& bytes, const std::filesystem::path& name) const = 0;
  // `straight_alpha`: RGB as stored, not multiplied by alpha (AlphaMode).
  virtual Image read(const std::string& bytes, const std::filesystem::path& name, bool straight_alpha) const = 0;
  // Empty when every pixel decodes, else why not (the codec's message).
  virtual std::string decode_problem(const std::string& bytes, const std::filesystem::path& name) const = 0;
  // stored_pixels() for an 8-bit format: the codec's own float conversion.
  virtual Image quantize_8bit(const Image& image) const = 0;
  // io/compare.h: the metrics but LDR-FLIP, and the heat map.
  virtual CompareMetrics compare(const Image& a, const Image& b, const CompareOptions& opts) const = 0;
  virtual Image diff_heatmap(const Image& a, const Image& b, float scale) const = 0;
  // A width x height canvas filled with `background`; text in DejaVu Sans
  // (Debian's fonts-dejavu-core), else OpenImageIO's default font, else none.
  virtual std::unique_ptr<ImageCanvas> canvas(int width, int height, const ImageCanvas::Color& background) const = 0;
};

// Starts loading the module on a background thread (once; later calls do
// nothing). Loading errors are kept for image_backend() to report.
void preload_image_backend();
// The loaded module, waiting for the load to finish. Throws Exit::system
// naming the module when it cannot be loaded.
const ImageBackend& image_backend();
// Where the module is looked for, in order: $MARCH_IMAGE_MODULE, beside the
// executable, ../lib/marchstudio/ from it (an installed tree), the build
// tree it was built in.
std::filesystem::path image_backend_path();

// What the module exports: a pointer to its one ImageBackend.
inline constexpr const char* kImageBackendSymbol = "marchstudio_image_backend";
inline constexpr const char* kImageBackendFile = "marchstudio-oiio.so";

}  // namespace ms
