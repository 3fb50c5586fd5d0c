#include "io/stored_pixels.h"

#include "io/image_backend.h"

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
  out.pixels = std::move(src);
  return image_backend().quantize_8bit(out);  // the codec's own float <-> UINT8
}

}  // namespace ms
