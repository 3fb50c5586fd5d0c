#include "io/stored_pixels.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include "core/error.h"

namespace ms {

Image stored_pixels(const Image& image, ImageFormat format) {
  if (!is_display_format(format)) return image;
  const int nch = image.nchannels();
  const bool drop_alpha = nch == 4 && image.channels[3] == "A";  // as write_image does
  const int out_ch = drop_alpha ? 3 : nch;
  const size_t npix = static_cast<size_t>(image.width) * image.height;
  Image out;
  out.width = image.width;
  out.height = image.height;
  out.channels.assign(image.channels.begin(), image.channels.begin() + out_ch);
  std::vector<float> src(npix * out_ch);
  for (size_t p = 0; p < npix; ++p)
    for (int c = 0; c < out_ch; ++c) src[p * out_ch + c] = image.pixels[p * nch + c];
  // Float -> UINT8 and back through OpenImageIO's conversions, the same
  // that write_image's encoder and read_image's decoder apply.
  std::vector<unsigned char> bytes(src.size());
  out.pixels.resize(src.size());
  const auto n = static_cast<OIIO::imagesize_t>(src.size());
  if (!OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, src.data(), OIIO::TypeDesc::UINT8, bytes.data(), n) ||
      !OIIO::convert_pixel_values(OIIO::TypeDesc::UINT8, bytes.data(), OIIO::TypeDesc::FLOAT, out.pixels.data(), n))
    fail_system("cannot convert pixels to 8 bits");
  return out;
}

}  // namespace ms
