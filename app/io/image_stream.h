// An image file written a band of rows at a time, for stills too large to
// hold whole (render/tiled_still.h): the rows go through the codec's
// scanline writes into the atomic temporary (io/atomic_file.h) as they
// come, and finish() verifies, fsyncs and renames it into place. Without
// finish() (an error, --strict, a signal) the temporary is removed and no
// file appears. The same encoding as write_image(): 8-bit formats drop an
// alpha channel "A", EXR keeps float; the metadata goes into the header.
//
//   ImageStreamWriter out(path, width, height, {"R", "G", "B", "A"}, meta);
//   out.write_rows(0, band);            // band.width == width, top row first
//   out.write_rows(band.height, next);  // in order, no gaps
//   out.finish();
//
// The codec is the image module's (io/image_backend.h, io/oiio/stream.cpp).
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/image.h"
#include "io/image_io.h"

namespace ms {

// What the image module implements (io/oiio/stream.cpp): rows in order,
// then finish() (or nothing: its destructor removes the temporary). Throw
// Exit::system naming the target on a failed write, as soon as it is seen.
class ImageRowWriter {
 public:
  virtual ~ImageRowWriter() = default;
  virtual void write_rows(int y0, const Image& rows) = 0;
  virtual void finish() = 0;
  virtual std::filesystem::path temp() const = 0;
};

// libjpeg's JPEG_MAX_DIMENSION.
inline constexpr int kMaxJpegSide = 65500;

class ImageStreamWriter {
 public:
  // Checks the path (check_output_path) and the size (a JPEG: at most
  // kMaxJpegSide), then creates the temporary; the header is written with
  // the first rows. Throws bad_input for the path or size, system for I/O.
  ImageStreamWriter(const std::filesystem::path& path, int width, int height, const std::vector<std::string>& channels,
                    const ImageMetadata& meta = {});
  ~ImageStreamWriter();
  ImageStreamWriter(const ImageStreamWriter&) = delete;
  ImageStreamWriter& operator=(const ImageStreamWriter&) = delete;

  // Rows y0 .. y0 + rows.height - 1, top row first; y0 must be the first
  // row not yet written, rows.width the image's and its channels those given.
  void write_rows(int y0, const Image& rows);
  // Every row written: close the codec, verify, fsync, rename.
  void finish();
  // Remove the temporary now; nothing is written.
  void discard();

 private:
  std::filesystem::path path_;
  int width_ = 0, height_ = 0;
  std::vector<std::string> channels_;
  int next_row_ = 0;
  std::unique_ptr<ImageRowWriter> rows_;
};

}  // namespace ms
