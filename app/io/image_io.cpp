#include "io/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <memory>
#include <unistd.h>

#include <climits>

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;

ImageFormat image_format_for(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::jpeg;
  if (ext == ".tif" || ext == ".tiff") return ImageFormat::tiff;
  if (ext == ".exr") return ImageFormat::exr;
  fail_input("unknown image extension '" + ext + "'", path.string(), 0, "-o",
             "use .png, .jpg, .tif or .exr");
}

bool is_display_format(ImageFormat f) { return f != ImageFormat::exr; }

void check_output_path(const fs::path& path) {
  image_format_for(path);
  if (path.filename().empty()) fail_input("output path names no file", path.string(), 0, "-o");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  check_output_directory(dir, "-o");
  std::error_code ec;
  if (fs::is_directory(path, ec)) fail_input("output path is a directory", path.string(), 0, "-o");
  const std::size_t name = path.filename().string().size(), limit = name_limit(dir);
  if (name > limit)
    fail_input("output file name is " + std::to_string(name) + " bytes, more than this file system's " +
                   std::to_string(limit),
               path.string(), 0, "-o");
  if (fs::absolute(path, ec).string().size() >= PATH_MAX)
    fail_input("output path is longer than PATH_MAX (" + std::to_string(PATH_MAX) + " bytes)", path.string(), 0, "-o");
}

namespace {

// OpenImageIO's codecs write through this. It never tells a codec that a
// write failed (OpenImageIO's PNG writer would go on regardless; libjpeg's
// default handler calls exit(1)); the AtomicFile records the failure and
// commit() reports it.
class AtomicProxy final : public OIIO::Filesystem::IOProxy {
 public:
  explicit AtomicProxy(AtomicFile& f) : IOProxy(f.target().string(), Write), f_(f) {}
  const char* proxytype() const override { return "marchstudio-atomic"; }
  size_t write(const void* buf, size_t n) override {
    f_.pwrite(buf, n, static_cast<std::uint64_t>(m_pos));
    m_pos += static_cast<int64_t>(n);
    return n;
  }
  size_t pwrite(const void* buf, size_t n, int64_t offset) override {
    f_.pwrite(buf, n, static_cast<std::uint64_t>(offset));
    return n;
  }
  size_t size() const override { return f_.size(); }

 private:
  AtomicFile& f_;
};

// An image file read by us (a FIFO or a device is refused) and opened by
// OpenImageIO from memory. The members go in reverse order: the input
// before the reader before the bytes it reads.
struct OpenedImage {
  std::unique_ptr<std::string> bytes;
  std::unique_ptr<OIIO::Filesystem::IOMemReader> mem;
  std::unique_ptr<OIIO::ImageInput> in;
};

OpenedImage open_image(const fs::path& path) {
  OpenedImage o;
  o.bytes = std::make_unique<std::string>(read_input_file(path, "image file", {}, kMaxImageInput));
  o.mem = std::make_unique<OIIO::Filesystem::IOMemReader>(o.bytes->data(), o.bytes->size());
  OIIO::ImageSpec config;
  o.in = OIIO::ImageInput::open(path.string(), &config, o.mem.get());
  if (!o.in) fail_input("cannot read image: " + OIIO::geterror(), path.string());
  return o;
}

}  // namespace

void write_image(const Image& image, const fs::path& path, const ImageMetadata& meta) {
  const ImageFormat format = image_format_for(path);
  check_output_path(path);
  // JPEG has no alpha; 8-bit outputs drop alpha generally (always 1 for renders).
  const int nch = image.nchannels();
  const bool drop_alpha = is_display_format(format) && nch == 4 && image.channels[3] == "A";
  const int out_ch = drop_alpha ? 3 : nch;

  OIIO::ImageSpec spec(image.width, image.height, out_ch,
                       is_display_format(format) ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.channelnames.assign(image.channels.begin(), image.channels.begin() + out_ch);
  spec.alpha_channel = (!drop_alpha && nch == 4 && image.channels[3] == "A") ? 3 : -1;
  if (format == ImageFormat::exr) spec.attribute("compression", "zip");
  if (format == ImageFormat::jpeg) spec.attribute("Compression", "jpeg:95");
  // Fast zlib settings: about 30% larger files, encoding about 3x faster,
  // which keeps sequence writing hidden behind rendering (docs/animation.md).
  if (format == ImageFormat::png) {
    spec.attribute("png:compressionLevel", 1);
    spec.attribute("png:filter", 16);  // PNG_FILTER_SUB
  }
  if (is_display_format(format)) spec.attribute("oiio:ColorSpace", "sRGB");
  else spec.attribute("oiio:ColorSpace", "Linear");
  for (const auto& [k, v] : meta) spec.attribute(k, v);

  AtomicFile file(path);
  AtomicProxy proxy(file);
  // The format comes from the target's name; the bytes go to the temporary:
  // through the proxy, which checks every write (PNG and JPEG do not), or
  // for TIFF by name, since libtiff rereads the directory it wrote (to link
  // the EXIF one) and checks its own writes.
  const bool by_name = format == ImageFormat::tiff;
  auto out = OIIO::ImageOutput::create(path.string(), by_name ? nullptr : &proxy);
  if (!out) fail_system("cannot create an image writer: " + OIIO::geterror(), path.string());
  const OIIO::stride_t xstride = static_cast<OIIO::stride_t>(nch * sizeof(float));
  const bool ok = out->open(by_name ? file.temp().string() : path.string(), spec) &&
                  out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data(), xstride) && out->close();
  if (by_name) file.written_by_name();
  const std::string err = ok ? "" : out->geterror();
  out.reset();
  if (!ok && by_name)  // the writer's own check failed: the same words as AtomicFile's
    fail_system("cannot write the file: " + err.substr(0, err.find('\n')) + "; nothing was written", path.string());
  if (!ok) fail_system("cannot write image: " + err, path.string());
  file.commit();
}

void add_fingerprint(ImageMetadata& meta, const std::string& fingerprint) {
  meta[kFingerprintKey] = fingerprint;
  std::string& d = meta["ImageDescription"];
  d += (d.empty() ? "" : " ") + std::string("fingerprint=") + fingerprint;
}

std::string fingerprint_from(std::string_view attribute, std::string_view description) {
  if (!attribute.empty()) return std::string(attribute);
  const std::string_view word = "fingerprint=";
  const size_t at = description.rfind(word);
  if (at == std::string_view::npos || (at > 0 && description[at - 1] != ' ')) return {};
  const std::string_view rest = description.substr(at + word.size());
  return std::string(rest.substr(0, rest.find(' ')));
}

ImageInfo read_image_info(const fs::path& path) {
  const OpenedImage opened = open_image(path);
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
  info.fingerprint = fingerprint_from(spec.get_string_attribute(kFingerprintKey),
                                      spec.get_string_attribute("ImageDescription"));
  return info;
}

Image read_image(const fs::path& path) {
  const OpenedImage opened = open_image(path);
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
    fail_input("cannot decode image: " + err, path.string());
  }
  in->close();
  return img;
}

}  // namespace ms
