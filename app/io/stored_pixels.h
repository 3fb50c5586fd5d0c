// The pixels an image file of a given format holds once write_image() has
// stored an Image: 8-bit formats drop a trailing alpha and round every
// value to one of 256 levels, with OpenImageIO's own conversion (the one
// write_image's encoder uses), and read back as read_image() reads them. So
// a render can be compared against an 8-bit reference in memory exactly as
// if it had been written and read again.
//
//   Image as_png = stored_pixels(render, ImageFormat::png);
#pragma once
#include "io/image.h"
#include "io/image_io.h"

namespace ms {

// EXR: unchanged. PNG, TIFF: exactly what reading the written file gives.
// JPEG: the 8-bit rounding only (its lossy coding is not modelled).
Image stored_pixels(const Image& image, ImageFormat format);

}  // namespace ms
