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

// Every backquoted name in the pages that `named` matches (its first
// group): `check` says whether it exists; returns how many were checked.
int check_named(const std::regex& named, bool (*check)(const std::string& name), const char* missing) {
  const fs::path root = MARCH_SOURCE_DIR;
  int checked = 0;
  for (const fs::path& page : pages()) {
    std::ifstream in(page);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      for (std::sregex_iterator it(line.begin(), line.end(), named), end; it != end; ++it) {
        ++checked;
        EXPECT_TRUE(check((*it)[1].str()))
            << fs::relative(page, root).string() << ":" << n << " names " << (*it)[1] << ", " << missing;
      }
  }
  return checked;
}

TEST(DocsPaths, EveryNamedRepositoryFileExists) {
  ASSERT_GT(pages().size(), 10u);
  const std::regex named("`((?:app|docs|notes|scenes|sdf_shaders|tests|tools)/[A-Za-z0-9_./-]+\\.[A-Za-z0-9]+)`");
  const int checked = check_named(
      named, [](const std::string& name) { return fs::exists(fs::path(MARCH_SOURCE_DIR) / name); }, "which does not exist");
  EXPECT_GT(checked, 100);  // the pattern still finds the pages' paths
}

// docs/architecture.md and others name sources by module (`io/sequence.h`,
// `pipeline/mesh_job.cpp`): each is a file under app/, or the template of
// a generated one (`core/version.h` from version.h.in).
TEST(DocsPaths, EveryNamedSourceFileExists) {
  const std::regex named(
      "`((?:core|gl|io|mesh|scene|preprocess|shader|importers|render|pipeline|bench|suite|sweep|live|cli)/"
      "[A-Za-z0-9_./-]+\\.(?:h|cpp))`");
  const int checked = check_named(
      named,
      [](const std::string& name) {
        const fs::path p = fs::path(MARCH_SOURCE_DIR) / "app" / name;
        return fs::exists(p) || fs::exists(p.string() + ".in");
      },
      "which is not under app/");
  EXPECT_GT(checked, 50);  // the pattern still finds the pages' sources
}

}  // namespace
