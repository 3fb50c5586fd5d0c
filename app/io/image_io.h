// Image files through OpenImageIO. 8-bit formats get display-encoded values
// (the renderer already applied tone map and sRGB); EXR stays float/linear.
// Every write is atomic: a temporary file in the target directory, then rename.
#pragma once
#include <filesystem>
#include <map>
#include <string>

#include "io/image.h"

namespace ms {

enum class ImageFormat { png, jpeg, tiff, exr };

// From the file extension, case-insensitive. Throws bad_input on an unknown one.
ImageFormat image_format_for(const std::filesystem::path& path);
// True for formats stored as 8-bit display values (PNG, JPEG, TIFF).
bool is_display_format(ImageFormat f);

// Check before any rendering that `path` can be written: known extension,
// existing directory, write permission. Throws bad_input naming the path.
void check_output_path(const std::filesystem::path& path);

// Extra metadata written into the file header ("Software", "ImageDescription", ...).
using ImageMetadata = std::map<std::string, std::string>;

// Write atomically. Throws bad_input for path problems, system for I/O errors;
// never leaves the target or the temporary behind on failure.
void write_image(const Image& image, const std::filesystem::path& path, const ImageMetadata& meta = {});

// write_image's temporary for `target`: a hidden sibling with the same
// extension (".<stem>.tmp<pid><ext>"), so OpenImageIO picks the same format.
std::filesystem::path temp_path_for(const std::filesystem::path& target, long pid);
// The file name of the target that `name` is a write_image temporary for,
// or empty when it is not one. Lets a resumed run clean up after a killed one.
std::string temp_target_name(const std::string& name);

// Read any format OpenImageIO knows, as float. Throws bad_input naming the file.
Image read_image(const std::filesystem::path& path);

}  // namespace ms
