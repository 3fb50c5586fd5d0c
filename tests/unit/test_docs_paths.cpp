// Every repository file the README and docs/*.md name in backquotes (a
// path under app/, docs/, notes/, scenes/, sdf_shaders/, tests/ or tools/)
// exists, so a page never sends a reader to a file that is gone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;

TEST(DocsPaths, EveryNamedRepositoryFileExists) {
  const fs::path root = MARCH_SOURCE_DIR;
  std::vector<fs::path> pages = {root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  ASSERT_GT(pages.size(), 10u);
  const std::regex named("`((?:app|docs|notes|scenes|sdf_shaders|tests|tools)/[A-Za-z0-9_./-]+\\.[A-Za-z0-9]+)`");
  int checked = 0;
  for (const fs::path& page : pages) {
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

}  // namespace
