#include "io/image_stream.h"

#include "core/error.h"
#include "io/image_backend.h"

namespace ms {

ImageStreamWriter::ImageStreamWriter(const std::filesystem::path& path, int width, int height,
                                     const std::vector<std::string>& channels, const ImageMetadata& meta)
    : path_(path), width_(width), height_(height), channels_(channels) {
  const ImageFormat format = image_format_for(path);
  check_output_path(path);
  if (format == ImageFormat::jpeg && (width > kMaxJpegSide || height > kMaxJpegSide))
    fail_input("a JPEG is at most " + std::to_string(kMaxJpegSide) + " pixels a side (libjpeg's limit), not " +
                   std::to_string(width) + "x" + std::to_string(height),
               path.string(), 0, "--size", "write a .png, .tif or .exr");
  rows_ = image_backend().open_rows(path, format, width, height, channels, meta);
}

ImageStreamWriter::~ImageStreamWriter() = default;  // without finish(): the module's writer removes the temporary

void ImageStreamWriter::write_rows(int y0, const Image& rows) {
  if (!rows_) fail_system("internal: rows written after the image was finished", path_.string());
  if (y0 != next_row_ || rows.width != width_ || rows.channels != channels_ || y0 + rows.height > height_)
    fail_system("internal: rows " + std::to_string(y0) + "+" + std::to_string(rows.height) +
                    " do not continue the image (next row " + std::to_string(next_row_) + ")",
                path_.string());
  rows_->write_rows(y0, rows);
  next_row_ += rows.height;
}

void ImageStreamWriter::finish() {
  if (!rows_) fail_system("internal: the image was finished twice", path_.string());
  if (next_row_ != height_)
    fail_system("internal: " + std::to_string(next_row_) + " of " + std::to_string(height_) + " rows written",
                path_.string());
  std::unique_ptr<ImageRowWriter> w = std::move(rows_);
  w->finish();
}

void ImageStreamWriter::discard() { rows_.reset(); }

}  // namespace ms
