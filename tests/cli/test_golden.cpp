// The golden suite's bookkeeping. The goldens themselves are checked by
// `marchstudio test tests/golden/suite.toml` (ctest: golden_suite, pinned to
// llvmpipe) and the cost bounds by `marchstudio test tests/cost/suite.toml`
// (ctest: cost_suite), as a user's CI would run them; this file checks that
// every scene is in both, has a golden and a gallery entry, and that the
// golden tolerances catch the subtlest regression they are meant to.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <map>
#include <sstream>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(source_dir() / "scenes"))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path golden_dir() { return source_dir() / "tests/golden"; }
fs::path golden_of(const std::string& scene) { return golden_dir() / (scene + ".png"); }

// `marchstudio test SUITE --list`: name -> reference ("-" when none).
std::map<std::string, std::string> listed(const fs::path& suite) {
  const RunResult r = run_marchstudio({"test", suite.string(), "--list"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, std::string> out;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cols;
    std::istringstream l(line);
    for (std::string c; std::getline(l, c, '\t');) cols.push_back(c);
    if (cols.size() == 4) out[cols[0]] = cols[3];
  }
  return out;
}

TEST(GoldenSuite, EverySceneHasAGoldenAndAGalleryEntry) {
  const std::vector<std::string> scenes = scene_names();
  ASSERT_FALSE(scenes.empty());
  const std::string gallery = read_file(source_dir() / "docs/gallery.md");
  for (const std::string& s : scenes) {
    EXPECT_TRUE(fs::exists(golden_of(s))) << s << ": run tools/update-goldens.sh";
    const fs::path copy = source_dir() / "docs/images/gallery" / (s + ".png");
    EXPECT_TRUE(fs::exists(copy) && read_file(copy) == read_file(golden_of(s)))
        << copy << " is not a copy of the golden: run tools/update-goldens.sh";
    EXPECT_NE(gallery.find("images/gallery/" + s + ".png"), std::string::npos) << "docs/gallery.md lacks " << s;
  }
  for (const auto& e : fs::directory_iterator(golden_dir()))
    if (e.path().extension() == ".png")
      EXPECT_TRUE(std::count(scenes.begin(), scenes.end(), e.path().stem().string()))
          << e.path() << " has no scene in scenes/";
}

// The suite globs scenes/, so this fails only if the glob or the backend
// list is broken, or a scene is excluded without a case of its own.
TEST(GoldenSuite, RendersEverySceneOnEglAndOsmesaAgainstItsGolden) {
  const auto cases = listed(golden_dir() / "suite.toml");
  for (const std::string& s : scene_names())
    for (const char* be : {"egl", "osmesa"}) {
      const std::string name = s + "." + be;
      ASSERT_TRUE(cases.count(name)) << "tests/golden/suite.toml has no case " << name;
      EXPECT_EQ(fs::path(cases.at(name)), golden_of(s)) << name;
    }
}

TEST(CostSuite, EverySceneHasCostBounds) {
  const auto cases = listed(source_dir() / "tests/cost/suite.toml");
  for (const std::string& s : scene_names())
    EXPECT_TRUE(cases.count(s)) << "tests/cost/suite.toml has no case \"" << s
                                << "\": add one (the block to copy is in the file's header)";
}

// The tolerances' reason to exist (tests/golden/suite.toml): moving seed's
// checker by 1 cm must fail both the psnr and the max check, with the
// suite's own thresholds.
TEST(GoldenSuite, TheTolerancesCatchTheSubtlestRegression) {
  const toml::table golden = toml::parse_file((golden_dir() / "suite.toml").string());
  const double psnr = golden["defaults"]["threshold"].value<double>().value_or(0);
  const double max = golden["defaults"]["check"][0]["threshold"].value<double>().value_or(0);
  ASSERT_GT(psnr, 0);
  ASSERT_GT(max, 0);
  TempDir dir;
  write_file(dir / "moved.toml", "[[case]]\nname = \"moved\"\nscene = \"" + (source_dir() / "scenes/seed.toml").string() +
                                     "\"\nreference = \"" + golden_of("seed").string() +
                                     "\"\nsize = [160, 90]\ntime = 0.02\nmetric = \"psnr\"\nthreshold = " +
                                     std::to_string(psnr) + "\n[[case.check]]\nmetric = \"max\"\nthreshold = " +
                                     std::to_string(max) + "\n[[case.check]]\nmetric = \"psnr\"\nthreshold = 40\n");
  const RunResult r = run_marchstudio({"test", (dir / "moved.toml").string(), "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const nlohmann::json checks = nlohmann::json::parse(r.out).at("cases").at(0).at("checks");
  ASSERT_EQ(checks.size(), 3u);
  EXPECT_EQ(checks[0].at("outcome"), "fail") << checks.dump();
  EXPECT_EQ(checks[1].at("outcome"), "fail") << checks.dump();
  EXPECT_EQ(checks[2].at("outcome"), "pass") << checks.dump();  // the same picture, moved (not a blank)
}

}  // namespace
}  // namespace ms::test
