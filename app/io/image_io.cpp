#include "io/image_io.h"

#include <unistd.h>

#include <climits>

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/direct_codec.h"
#include "io/image_backend.h"
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

const char* format_extension(ImageFormat f) {
  switch (f) {
    case ImageFormat::png: return "png";
    case ImageFormat::jpeg: return "jpg";
    case ImageFormat::tiff: return "tif";
    case ImageFormat::exr: return "exr";
  }
  return "png";
}

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

// PNG and EXR by libpng and OpenEXR (io/direct_codec.h), the rest by the
// image module (io/image_backend.h, io/oiio/codec.cpp).
void write_image(const Image& image, const fs::path& path, const ImageMetadata& meta) {
  const ImageFormat format = image_format_for(path);
  check_output_path(path);
  if (writes_directly(format)) write_direct(image, path, format, meta);
  else image_backend().write(image, path, format, meta);
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

namespace {

std::string read_image_bytes(const fs::path& path) {
  return read_input_file(path, "image file", {}, kMaxImageInput);
}

std::string attribute(const ImageInfo& info, std::string_view name) {
  for (const auto& [k, v] : info.attributes)
    if (k == name) return v;
  return {};
}

}  // namespace

ImageInfo read_image_info(const fs::path& path) {
  ImageInfo info = image_backend().read_info(read_image_bytes(path), path);
  info.fingerprint = fingerprint_of(info);
  return info;
}

std::string fingerprint_of(const ImageInfo& info) {
  return fingerprint_from(attribute(info, kFingerprintKey), attribute(info, "ImageDescription"));
}

Image read_image(const fs::path& path, AlphaMode alpha) {
  return image_backend().read(read_image_bytes(path), path, alpha == AlphaMode::straight);
}

}  // namespace ms
