// Every file marchstudio reads comes through here: a regular file, opened
// without blocking and read to the end, or one honest error naming it.
// A FIFO would block the open forever, /dev/zero never ends, and a
// directory is not "not found".
//
//   std::string text = read_input_file("scene.toml", "scene file");
//   check_input_file(path, "reference image", "--reference");  // no read
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace ms {

// Text inputs (scenes, shaders) beyond this are refused before reading:
// the preprocessor's own budget is smaller (preprocess/macro_engine.h).
inline constexpr std::size_t kMaxTextInput = std::size_t{64} << 20;
// Image inputs, compressed.
inline constexpr std::size_t kMaxImageInput = std::size_t{4} << 30;

// Why `path` is not a readable regular file: "not found", "is a directory",
// "is a FIFO, not a regular file", "is a device, not a regular file", "is
// not readable (permission denied)" ...; empty when it is one.
std::string input_file_problem(const std::filesystem::path& path);

// A descriptor on `path` for reading, or -1 with `why` set to a problem as
// above: opened with O_NONBLOCK (a FIFO returns at once instead of waiting
// for a writer), then checked on the open file itself (fstat) to be a
// regular file; reads block as usual after. `follow_links` false: a link
// at `path` itself is refused ("is a symbolic link, not followed"), as a
// cache entry or stamp that marchstudio only ever writes as a file is.
// The caller closes it.
int open_regular_file(const std::filesystem::path& path, std::string& why, bool follow_links = true);

// Throws bad_input "<what> <problem>" at `path` (and `key`) unless
// input_file_problem() is empty.
void check_input_file(const std::filesystem::path& path, std::string_view what, std::string_view key = {});

// The whole file. Throws bad_input as check_input_file() does, for a file
// over `max_bytes`, and system for a read that fails half way. The check
// is made on the opened file itself (fstat), so a file swapped for a FIFO
// after the check is still refused.
std::string read_input_file(const std::filesystem::path& path, std::string_view what, std::string_view key = {},
                            std::size_t max_bytes = kMaxTextInput);

}  // namespace ms
