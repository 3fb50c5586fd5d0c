// The VS Code loader's four-buffer limit applies while it walks the files
// (importers/vscode.cpp): a chain of buffer files naming each other stops at
// the fifth, unread, so 20,000 such files cost five reads, not 20,000.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "files.h"
#include "importers/vscode.h"

namespace ms {
namespace {
namespace fs = std::filesystem;

TEST(VsCodeBufferWalk, AChainStopsAtTheFifthBufferBeforeReadingIt) {
  const test::TempDir tmp;
  const fs::path dir = tmp.path();
  const std::string image = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";
  const auto name = [](int i) { return "b" + std::to_string(i) + ".glsl"; };
  // main -> b1 -> b2 -> ... -> b29; b5 is a directory (unreadable as a
  // shader), b10 is missing: neither may be what the error is about.
  for (int i = 1; i < 30; ++i) {
    if (i == 5) {
      fs::create_directories(dir / name(i));
      continue;
    }
    if (i == 10) continue;
    std::ofstream(dir / name(i)) << "#iChannel0 \"file://" << name(i + 1) << "\"\n" << image;
  }
  const std::string main = "#iChannel0 \"file://b1.glsl\"\n" + image;
  std::string what;
  try {
    load_vscode(main, dir / "main.glsl", {dir});
    ADD_FAILURE() << "a chain of 29 buffers was accepted";
  } catch (const Error& e) {
    what = e.info().what;
    EXPECT_EQ(fs::path(e.info().file).filename(), "b4.glsl");
    EXPECT_EQ(e.info().line, 1);
    EXPECT_EQ(e.info().key, "#iChannel0");
  }
  EXPECT_NE(what.find("b5.glsl' would be a 5th buffer: marchstudio runs at most 4"), std::string::npos) << what;
  EXPECT_EQ(what.find("b10"), std::string::npos) << what;
  EXPECT_EQ(what.find("directory"), std::string::npos) << what;
}

}  // namespace
}  // namespace ms
