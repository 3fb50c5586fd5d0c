// Shared by the fuzz targets: a scratch directory per process with the
// files a target needs, and the canary that confinement must never leak.
// Each target is a plain LLVMFuzzerTestOneInput: linked with -fsanitize=fuzzer
// it is a libFuzzer binary (MARCH_FUZZ=ON), linked with replay_main.cpp it
// replays the seed corpus and the regression inputs in the normal test suite.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace ms::fuzz {

namespace fs = std::filesystem;

// Text a confined include must never bring into a shader or an error.
inline constexpr std::string_view kCanary = "CANARY_outside_the_roots_7f3a";

inline void put(const fs::path& p, std::string_view text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
}

// <tmp>/marchfuzz-XXXXXX/ with:
//   scene/            the scene's directory (an include root)
//   scene/escape.glsl a symlink to secret/secret.glsl (outside every root)
//   scene/up          a symlink to the workspace itself
//   lib/              a second root (the shader library's role)
//   secret/secret.glsl  the canary, outside the roots
// Removed at exit.
class Workspace {
 public:
  Workspace() {
    std::string tmpl = (fs::temp_directory_path() / "marchfuzz-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) std::abort();
    root_ = tmpl;
    put(root_ / "secret/secret.glsl", std::string(kCanary) + "\nfloat secret() { return 1.0; }\n");
    put(root_ / "lib/lib.glsl", "float lib() { return 2.0; }\n");
    fs::create_directories(root_ / "scene");
    std::error_code ec;
    fs::create_symlink(root_ / "secret/secret.glsl", root_ / "scene/escape.glsl", ec);
    fs::create_directory_symlink(root_, root_ / "scene/up", ec);
  }
  ~Workspace() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  const fs::path& root() const { return root_; }
  fs::path scene() const { return root_ / "scene"; }
  fs::path lib() const { return root_ / "lib"; }

 private:
  fs::path root_;
};

inline Workspace& workspace() {
  static Workspace w;
  return w;
}

inline bool leaks_canary(std::string_view text) { return text.find(kCanary) != std::string_view::npos; }

// A property violation: report and crash so libFuzzer keeps the input.
[[noreturn]] inline void violated(const char* what, std::string_view detail) {
  std::fprintf(stderr, "fuzz property violated: %s\n%.*s\n", what, static_cast<int>(detail.size()), detail.data());
  std::abort();
}

}  // namespace ms::fuzz
