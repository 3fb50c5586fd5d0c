// Image files through OpenImageIO: what read_image() and read_image_info()
// (io/image_io.h) do once their checks are made; writes are stream.cpp's.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "core/error.h"
#include "core/memory_budget.h"
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

// OpenImageIO's error text, one message a line, as one clause: the one-line
// error would otherwise show its line breaks escaped as "\\n".
std::string oiio_text(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 2)) text.replace(at, 1, "; ");
  return text;
}

OpenedImage open_image(const std::string& bytes, const fs::path& name, bool straight_alpha = false) {
  OpenedImage o;
  o.mem = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes.data(), bytes.size());
  OIIO::ImageSpec config;
  // Without this, the PNG and TIFF readers multiply RGB by alpha.
  if (straight_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
  o.in = OIIO::ImageInput::open(name.string(), &config, o.mem.get());
  if (!o.in) fail_input("cannot read image: " + oiio_text(OIIO::geterror()), name.string());
  return o;
}

// The decoded floats a header declares, over the memory budget: why not
// to read it (a 69-byte PNG can declare 100000x100000), else empty.
std::string over_budget(const OIIO::ImageSpec& spec) {
  const double bytes = 4.0 * spec.width * spec.height * std::max(spec.depth, 1) * spec.nchannels;
  if (bytes <= memory_budget()) return {};
  return "the image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " with " +
         std::to_string(spec.nchannels) + " channels: its pixels need " + format_bytes(bytes) + ", over the " +
         format_bytes(memory_budget()) + " memory budget";
}

// A JPEG cut short decodes without an error (libjpeg pads the rest with
// grey and only warns), so: its scan data must reach an end-of-image
// marker. In entropy-coded data a 0xFF byte is always followed by 0x00 or
// a restart marker, so FF D9 after the first scan is the real end; an
// EXIF thumbnail's own markers sit in an APP segment, skipped by length.
bool jpeg_cut_short(const std::string& b) {
  if (b.size() < 4 || static_cast<unsigned char>(b[0]) != 0xFF || static_cast<unsigned char>(b[1]) != 0xD8)
    return false;  // not a JPEG: its reader says so
  size_t i = 2;
  while (i + 4 <= b.size()) {
    const unsigned char m = static_cast<unsigned char>(b[i + 1]);
    if (static_cast<unsigned char>(b[i]) != 0xFF || m == 0xFF) {  // stray bytes (libjpeg skips them too), fill
      ++i;
      continue;
    }
    if (m == 0xD9) return false;       // an image with no scan: its reader decides
    const size_t len = (static_cast<size_t>(static_cast<unsigned char>(b[i + 2])) << 8) |
                       static_cast<unsigned char>(b[i + 3]);
    if (m == 0xDA) {
      for (size_t j = i + 2 + len; j + 1 < b.size(); ++j)
        if (static_cast<unsigned char>(b[j]) == 0xFF && static_cast<unsigned char>(b[j + 1]) == 0xD9) return false;
      return true;
    }
    i += 2 + len;
  }
  return true;
}

bool is_jpeg(const OIIO::ImageInput* in) { return std::string(in->format_name()) == "jpeg"; }

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
  if (const std::string why = over_budget(spec); !why.empty())
    fail_input(why, name.string(), 0, {}, "scale it down");
  if (is_jpeg(in) && jpeg_cut_short(bytes))
    fail_input("cannot decode image: the JPEG data ends before its end-of-image marker (a file cut short)",
               name.string());
  img.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
    fail_input("cannot decode image: " + oiio_text(in->geterror()), name.string());
  }
  in->close();
  return img;
}

std::string decode_problem(const std::string& bytes, const fs::path& name) {
  OIIO::Filesystem::IOMemReader mem(bytes.data(), bytes.size());
  OIIO::ImageSpec config;
  auto in = OIIO::ImageInput::open(name.string(), &config, &mem);
  if (!in) return "unreadable: " + oiio_text(OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (std::string why = over_budget(spec); !why.empty()) return why;
  if (is_jpeg(in.get()) && jpeg_cut_short(bytes)) return "cut short: the JPEG data ends before its end-of-image marker";
  // In the file's own pixel type: the cheapest full decode.
  std::vector<unsigned char> pixels(spec.image_bytes());
  if (!in->read_image(0, 0, 0, spec.nchannels, spec.format, pixels.data()))
    return "cannot decode: " + oiio_text(in->geterror());
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
