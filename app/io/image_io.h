// Image files through OpenImageIO, in the module io/image_backend.h loads. 8-bit formats get display-encoded values
// (the renderer already applied tone map and sRGB); EXR stays float/linear.
// Every write goes through io/atomic_file.h (verified, then renamed into
// place) and every read through io/input_file.h (regular files only).
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/image.h"

namespace ms {

enum class ImageFormat { png, jpeg, tiff, exr };

// From the file extension, case-insensitive. Throws bad_input on an unknown one.
ImageFormat image_format_for(const std::filesystem::path& path);
// The extension a file of the format is named with, without the dot: png, jpg, tif, exr.
const char* format_extension(ImageFormat f);
// True for formats stored as 8-bit display values (PNG, JPEG, TIFF).
inline bool is_display_format(ImageFormat f) { return f != ImageFormat::exr; }

// True when the name's extension (any case) is one of the image formats an
// input may be read from, the ones VS Code's extension sorts as images.
// Inline: the shader importers (and the parser-only fuzz build) use it
// without linking the image readers.
inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}
inline bool is_image_name(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  for (const char* e : {".png", ".jpg", ".jpeg", ".bmp", ".gif", ".webp", ".tga", ".tif", ".tiff", ".exr", ".hdr"})
    if (ext == e) return true;
  return false;
}
// The high-dynamic-range ones (.exr, .hdr): read into float textures, not 8-bit.
inline bool is_float_image_name(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".hdr";
}

// Check before any rendering that `path` can be written: known extension,
// existing directory, write permission, a name within the file system's
// limit (NAME_MAX, PATH_MAX). Throws bad_input naming the path.
void check_output_path(const std::filesystem::path& path);

// Extra metadata written into the file header ("Software", "ImageDescription", ...).
using ImageMetadata = std::map<std::string, std::string>;

// Write atomically (io/atomic_file.h). Throws bad_input for path problems,
// system for I/O errors (a full disk: exit 3, one line); never leaves the
// target or the temporary behind on failure.
void write_image(const Image& image, const std::filesystem::path& path, const ImageMetadata& meta = {});

// The fingerprint of what made an image (pipeline/fingerprint.h), in two places
// so that every format keeps it: the "marchstudio:fingerprint" attribute
// (a PNG text chunk, an EXR header attribute) and a last
// "fingerprint=<hex>" word of ImageDescription (which TIFF and JPEG keep).
inline constexpr const char* kFingerprintKey = "marchstudio:fingerprint";
void add_fingerprint(ImageMetadata& meta, const std::string& fingerprint);
// The fingerprint from an image's attribute, else its description; empty if none.
std::string fingerprint_from(std::string_view attribute, std::string_view description);

// An image file's header: size, channels, and its text attributes.
struct ImageInfo {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::string format;       // "png", "openexr", ...
  std::string pixel_type;   // "uint8", "float", ...
  std::string fingerprint;  // empty when it has none
  std::vector<std::pair<std::string, std::string>> attributes;  // string-valued ones, in file order
};
// Reads the header only, from a regular file. Throws bad_input naming it.
ImageInfo read_image_info(const std::filesystem::path& path);
// fingerprint_from() over an info's attributes.
std::string fingerprint_of(const ImageInfo& info);

// How the RGB of a file with an alpha channel is read: `associated`
// multiplied by alpha (OpenImageIO's default for PNG and TIFF; what
// `compare` and `test` read), `straight` as stored (a Shadertoy texture's
// texels are the file's bytes). EXR is associated in the file: the same
// either way.
enum class AlphaMode { associated, straight };

// Read any format OpenImageIO knows, as float, from a regular file (io/
// input_file.h). Throws bad_input naming the file.
Image read_image(const std::filesystem::path& path, AlphaMode alpha = AlphaMode::associated);

}  // namespace ms
