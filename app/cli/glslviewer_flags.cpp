#include "cli/glslviewer_flags.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "io/image_io.h"

namespace ms {

namespace {

// A whole positive number of pixels, as glslViewer's -w and -h take.
bool is_pixels(const char* s) {
  if (!s || !*s) return false;
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  return *end == '\0' && v > 0;
}

// glslViewer's -E takes a command ("screenshot,out.png") or a file: the file.
std::string export_file(std::string_view v) {
  const std::size_t comma = v.rfind(',');
  return std::string(comma == std::string_view::npos ? v : v.substr(comma + 1));
}

}  // namespace

bool is_input_name(const std::string& arg) {
  const std::string ext = std::filesystem::path(arg).extension().string();
  return ext == ".toml" || ext == ".glsl" || ext == ".frag" || ext == ".fs" || ext == ".json";
}

bool opens_in_viewer(const std::string& arg) {
  std::error_code ec;
  return is_input_name(arg) && std::filesystem::is_regular_file(arg, ec);
}

void refuse_image_inputs(const std::vector<std::string>& inputs) {
  for (const std::string& in : inputs)
    if (is_image_name(in))
      fail_input("an image, not a scene or a shader", in, 0, {}, "bind it to a glslViewer shader with --texture " + in);
}

std::string glslviewer_habit(int argc, char** argv) {
  std::vector<std::string> seen;
  std::string width, height, file;
  bool headless = false;
  for (int i = 2; i < argc; ++i) {  // argv[1] is the subcommand
    const std::string_view a = argv[i];
    const char* next = i + 1 < argc ? argv[i + 1] : nullptr;
    if (a == "--") break;
    if (a == "-w") {
      seen.push_back("-w");
      if (is_pixels(next)) width = argv[++i];
    } else if (a == "-h" && is_pixels(next)) {
      seen.push_back("-h");
      height = argv[++i];
    } else if (a == "-E") {
      seen.push_back("-E");
      if (next) file = export_file(argv[++i]);
    } else if (a == "--headless") {
      seen.push_back("--headless");
      headless = true;
    }
  }
  if (seen.empty()) return {};
  std::string flags;
  for (std::size_t i = 0; i < seen.size(); ++i)
    flags += (i == 0 ? "" : i + 1 == seen.size() ? " and " : ", ") + seen[i];
  std::vector<std::string> use;
  if (!width.empty() || !height.empty() || std::find(seen.begin(), seen.end(), "-w") != seen.end())
    use.push_back("--size " + (width.empty() ? std::string("W") : width) + "x" +
                  (height.empty() ? std::string("H") : height) + " for the image size");
  if (std::find(seen.begin(), seen.end(), "-E") != seen.end())
    use.push_back("-o " + (file.empty() ? std::string("FILE") : file) + " for the image file");
  std::string hint;
  for (std::size_t i = 0; i < use.size(); ++i) hint += (i == 0 ? "use " : " and ") + use[i];
  if (headless)
    hint += std::string(hint.empty() ? "" : "; ") + "drop --headless: marchstudio render draws without a window";
  const bool one = seen.size() == 1;
  return format_error({Exit::bad_input, {}, 0, {},
                       flags + (one ? " is a glslViewer flag" : " are glslViewer flags") +
                           (height.empty() ? "" : ", and here -h is help"),
                       hint, {}});
}

}  // namespace ms
