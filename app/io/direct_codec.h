// PNG and OpenEXR written with libpng and OpenEXR themselves, the codecs
// OpenImageIO would call: the two formats renders are written in, without
// loading OpenImageIO and its ~260 libraries (0.25 s, three times a 640x360
// still's own work; docs/performance.md#start-up). The files hold what
// OpenImageIO would write: the same 8-bit rounding, the same compression
// settings, and the metadata under the names it writes and reads back
// (ImageDescription as PNG "Description" and EXR "comments").
// tests/unit/test_direct_codec.cpp checks both against OpenImageIO's.
//
//   if (writes_directly(format)) write_direct(image, path, format, meta);
#pragma once
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "io/image.h"
#include "io/image_io.h"

namespace ms {

bool writes_directly(ImageFormat format);  // png and exr

// Through io/atomic_file.h: verified, then renamed; throws Exit::system
// (a full disk, an I/O error) naming the path, leaving nothing behind.
// 8-bit formats drop a trailing "A" channel, as write_image() does.
void write_direct(const Image& image, const std::filesystem::path& path, ImageFormat format,
                  const ImageMetadata& meta);

// OpenImageIO's float -> UINT8 conversion (convert_pixel_values): v * 255
// in float, clamped to [0, 255], rounded half away from zero (roundf, not
// + 0.5, whose own rounding turns 0.49999997 into 1); NaN gives 0.
// tests/unit/test_direct_codec.cpp holds it to OIIO's on both sides of
// every level.
inline std::uint8_t to_display_byte(float v) {
  float s = v * 255.0f;
  s = s >= 0.0f ? (s <= 255.0f ? s : 255.0f) : 0.0f;
  return static_cast<std::uint8_t>(std::round(s));
}

}  // namespace ms
