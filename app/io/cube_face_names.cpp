// cube_faces.h's file naming, apart from the image reading: the parsers
// (importers/vscode.cpp) name a cubemap's faces without linking the codecs,
// and so does the fuzz build (tests/fuzz).
#include <string>

#include "io/cube_faces.h"

namespace fs = std::filesystem;

namespace ms {

std::array<fs::path, 6> cube_face_files(const fs::path& first) {
  std::array<fs::path, 6> out;
  out[0] = first;
  for (int i = 1; i < 6; ++i)
    out[i] = first.parent_path() / (first.stem().string() + "_" + std::to_string(i) + first.extension().string());
  return out;
}

std::array<fs::path, 6> cube_wildcard_files(const std::string& pattern) {
  static const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
  std::array<fs::path, 6> out;
  const size_t at = pattern.find("{}");
  if (at == std::string::npos) return out;
  for (int i = 0; i < 6; ++i) out[i] = std::string(pattern).replace(at, 2, names[i]);
  return out;
}

}  // namespace ms
