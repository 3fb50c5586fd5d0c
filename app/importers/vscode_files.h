// A VS Code shader (the Shader Toy extension's `#iChannel` files) read
// into its files: the main file and every file it reads through its
// directives, in post-order, each directive replaced by its GLSL and its
// channels resolved within the include roots (importers/vscode.h makes the
// project of them). Each mistake is one line naming the file, line and
// directive.
//
//   std::vector<VsFile> files = read_vscode_files(text, "main.glsl", roots);  // the main file last
#pragma once
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ms {

inline constexpr const char* kVscodeDoc = "docs/vscode.md lists what runs";

enum class VsKind { shader, image, audio, video };

struct VsChannel {
  int line = 0;                 // of its #iChannelN "..." line; 0: none
  bool self = false;
  std::filesystem::path path;   // absolute, normalised
  VsKind kind = VsKind::shader;
  std::optional<std::string> min, mag, wrap, type;
  int type_line = 0, min_line = 0, mag_line = 0, wrap_line = 0;
};

struct VsFile {
  std::filesystem::path path;
  std::string where;
  std::string code;             // directives replaced by their one-line GLSL (or blank)
  std::array<VsChannel, 4> ch{};
  int keyboard_line = 0;
  bool uses_main = false;       // void main() with gl_FragColor, the extension's other entry point
  std::string from_where;       // the directive that first named it
  int from_line = 0;
};

// The directive a (comment-free) line starts with: "iChannel2", "iKeyboard"...;
// empty when it starts with none of the extension's.
std::string directive_name(const std::string& line);

std::vector<VsFile> read_vscode_files(const std::string& text, const std::filesystem::path& file,
                                      const std::vector<std::filesystem::path>& roots);

}  // namespace ms
