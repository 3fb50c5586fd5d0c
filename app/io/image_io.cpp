#include "io/image_io.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"

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
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    fail_input("output directory does not exist", dir.string(), 0, "-o");
  if (::access(dir.c_str(), W_OK) != 0)
    fail_input("output directory is not writable", dir.string(), 0, "-o");
  if (fs::is_directory(path, ec)) fail_input("output path is a directory", path.string(), 0, "-o");
}

fs::path temp_path_for(const fs::path& target, long pid) {
  std::string name = ".";
  name.append(target.stem().string()).append(".tmp").append(std::to_string(pid));
  name.append(target.extension().string());
  return target.parent_path() / name;
}

std::string temp_target_name(const std::string& name) {
  const size_t at = name.rfind(".tmp");
  if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at < 1) return {};
  const size_t digits_end = name.find_first_not_of("0123456789", at + 4);
  if (digits_end == at + 4) return {};  // no pid
  const std::string ext = digits_end == std::string::npos ? "" : name.substr(digits_end);
  if (!ext.empty() && (ext[0] != '.' || ext.find('.', 1) != std::string::npos)) return {};
  return name.substr(1, at - 1) + ext;
}

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

  const fs::path tmp = temp_path_for(path, ::getpid());
  auto out = OIIO::ImageOutput::create(tmp.string());
  if (!out) fail_system("cannot create an image writer: " + OIIO::geterror(), path.string());
  const OIIO::stride_t xstride = static_cast<OIIO::stride_t>(nch * sizeof(float));
  bool ok = out->open(tmp.string(), spec) &&
            out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data(), xstride) && out->close();
  if (!ok) {
    const std::string err = out->geterror();
    out.reset();
    std::error_code ec;
    fs::remove(tmp, ec);
    fail_system("cannot write image: " + err, path.string());
  }
  out.reset();
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail_system("cannot rename temporary image into place: " + ec.message(), path.string());
  }
}

Image read_image(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail_input("image file not found", path.string());
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) fail_input("cannot read image: " + OIIO::geterror(), path.string());
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
