// Every shipped scene (globbed: a new one cannot slip in) renders clean:
// `bench --strict` finds no NaN/Inf pixel (exit 1 otherwise), and its
// bounds check (render/bounds_check.h) finds nothing of map() outside the
// scene's [bounds]. Its cost bounds are tests/cost/suite.toml's.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "run.h"

namespace ms::test {
namespace {

class CleanScene : public ::testing::TestWithParam<std::string> {};

TEST_P(CleanScene, HasNoNonFinitePixelAndKeepsItsBounds) {
  const RunResult r = run_marchstudio({"bench", (source_dir() / "scenes" / (GetParam() + ".toml")).string(), "--size",
                                       "160x90", "--frames", "1", "--warmup", "0", "--json", "--strict"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning: map() is negative on the [bounds] surface"), std::string::npos) << r.err;
}

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(source_dir() / "scenes"))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Scenes, CleanScene, ::testing::ValuesIn(scene_names()));

}  // namespace
}  // namespace ms::test
