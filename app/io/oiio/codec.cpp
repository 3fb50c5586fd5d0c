// Image files through OpenImageIO: what read_image() and read_image_info()
// (io/image_io.h) do once their checks are made; writes are stream.cpp's.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/error.h"
#include "io/oiio/oiio.h"

namespace ms::oiio {
namespace fs = std::filesystem;

namespace {

// An image opened by OpenImageIO from the bytes we read (io/input_file.h:
// a FIFO or a device is refused before this). The reader goes before the
// input that reads through it.
struct OpenedImage {
  std::unique_ptr<OIIO::Filesystem::IOMemReader> mem;
  std::unique_ptr<OIIO::ImageInput> in;
};

OpenedImage open_image(const std::string& bytes, const fs::path& name, bool straight_alpha = false) {
  OpenedImage o;
  o.mem = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes.data(), bytes.size());
  OIIO::ImageSpec config;
  // Without this, the PNG and TIFF readers multiply RGB by alpha.
  if (straight_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
  o.in = OIIO::ImageInput::open(name.string(), &config, o.mem.get());
  if (!o.in) fail_input("cannot read image: " + OIIO::geterror(), name.string());
  return o;
}

}  // namespace

ImageInfo read_info(const std::string& bytes, const fs::path& name) {
  const OpenedImage opened = open_image(bytes, name);
  OIIO::ImageInput* in = opened.in.get();
  const OIIO::ImageSpec& spec = in->spec();
  ImageInfo info;
  info.width = spec.width;
  info.height = spec.height;
  info.channels.assign(spec.channelnames.begin(), spec.channelnames.end());
  info.format = in->format_name();
  info.pixel_type = spec.format.c_str();
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING) info.attributes.emplace_back(p.name().string(), p.get_string());
  return info;
}

Image read(const std::string& bytes, const fs::path& name, bool straight_alpha) {
  const OpenedImage opened = open_image(bytes, name, straight_alpha);
  OIIO::ImageInput* in = opened.in.get();
  const OIIO::ImageSpec& spec = in->spec();
  Image img;
  img.width = spec.width;
  img.height = spec.height;
  for (int c = 0; c < spec.nchannels; ++c)
    img.channels.push_back(c < static_cast<int>(spec.channelnames.size()) ? spec.channelnames[c]
                                                                          : std::string("C").append(std::to_string(c)));
  img.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
    const std::string err = in->geterror();
    fail_input("cannot decode image: " + err, name.string());
  }
  in->close();
  return img;
}

std::string decode_problem(const std::string& bytes, const fs::path& name) {
  OIIO::Filesystem::IOMemReader mem(bytes.data(), bytes.size());
  OIIO::ImageSpec config;
  auto in = OIIO::ImageInput::open(name.string(), &config, &mem);
  if (!in) return "unreadable: " + OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  // In the file's own pixel type: the cheapest full decode.
  std::vector<unsigned char> pixels(spec.image_bytes());
  if (!in->read_image(0, 0, 0, spec.nchannels, spec.format, pixels.data()))
    return "cannot decode: " + in->geterror();
  return {};
}

Image quantize_8bit(const Image& image) {
  // Float -> UINT8 and back through OpenImageIO's conversions, the same
  // that write()'s encoder and read()'s decoder apply.
  Image out = image;
  std::vector<unsigned char> bytes(image.pixels.size());
  const auto n = static_cast<OIIO::imagesize_t>(image.pixels.size());
  if (!OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, image.pixels.data(), OIIO::TypeDesc::UINT8, bytes.data(),
                                  n) ||
      !OIIO::convert_pixel_values(OIIO::TypeDesc::UINT8, bytes.data(), OIIO::TypeDesc::FLOAT, out.pixels.data(), n))
    fail_system("cannot convert pixels to 8 bits");
  return out;
}

}  // namespace ms::oiio
