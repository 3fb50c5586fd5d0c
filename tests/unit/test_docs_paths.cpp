// Every repository file the README and docs/*.md name in backquotes (a
// path under app/, docs/, notes/, scenes/, sdf_shaders/, tests/ or tools/,
// or a source file by its module, `io/image_io.h`) exists, so a page never
// sends a reader to a file that is gone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;

std::vector<fs::path> pages() {
  const fs::path root = MARCH_SOURCE_DIR;
  std::vector<fs::path> out = {root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") out.push_back(e.path());
  return out;
}

TEST(DocsPaths, EveryNamedRepositoryFileExists) {
  const fs::path root = MARCH_SOURCE_DIR;
  ASSERT_GT(pages().size(), 10u);
  const std::regex named("`((?:app|docs|notes|scenes|sdf_shaders|tests|tools)/[A-Za-z0-9_./-]+\\.[A-Za-z0-9]+)`");
  int checked = 0;
  for (const fs::path& page : pages()) {
    std::ifstream in(page);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      for (std::sregex_iterator it(line.begin(), line.end(), named), end; it != end; ++it) {
        ++checked;
        EXPECT_TRUE(fs::exists(root / (*it)[1].str()))
            << fs::relative(page, root).string() << ":" << n << " names " << (*it)[1] << ", which does not exist";
      }
  }
  EXPECT_GT(checked, 100);  // the pattern still finds the pages' paths
}

// docs/architecture.md and others name sources by module (`io/sequence.h`,
// `pipeline/mesh_job.cpp`): each is a file under app/, or the template of
// a generated one (`core/version.h` from version.h.in).
TEST(DocsPaths, EveryNamedSourceFileExists) {
  const fs::path app = fs::path(MARCH_SOURCE_DIR) / "app";
  const std::regex named(
      "`((?:core|gl|io|mesh|scene|preprocess|shader|importers|render|pipeline|bench|suite|sweep|live|cli)/"
      "[A-Za-z0-9_./-]+\\.(?:h|cpp))`");
  int checked = 0;
  for (const fs::path& page : pages()) {
    std::ifstream in(page);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      for (std::sregex_iterator it(line.begin(), line.end(), named), end; it != end; ++it) {
        ++checked;
        const fs::path p = app / (*it)[1].str();
        EXPECT_TRUE(fs::exists(p) || fs::exists(p.string() + ".in"))
            << page.filename().string() << ":" << n << " names " << (*it)[1] << ", which is not under app/";
      }
  }
  EXPECT_GT(checked, 50);  // the pattern still finds the pages' sources
}

}  // namespace
