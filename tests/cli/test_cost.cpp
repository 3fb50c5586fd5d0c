// Cost regression: every scene's mean primary steps per pixel and step-cap
// fraction, from `bench --json`'s deterministic counting pass, stay under
// the bounds in tests/cost/bounds.toml. No wall-clock time is involved.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>

#include "run.h"

namespace ms::test {
namespace {

class Cost : public ::testing::TestWithParam<std::string> {};

TEST_P(Cost, StaysWithinItsBounds) {
  const std::string name = GetParam();
  const toml::table bounds = toml::parse_file((source_dir() / "tests/cost/bounds.toml").string());
  const std::string size = bounds["size"].value_or(std::string());
  const std::optional<double> max_steps = bounds[name]["mean_primary_steps"].value<double>();
  const std::optional<double> max_cap = bounds[name]["step_cap_fraction"].value<double>();
  ASSERT_FALSE(size.empty());
  ASSERT_TRUE(max_steps && max_cap) << "tests/cost/bounds.toml has no complete [" << name << "]";

  const RunResult r = run_marchstudio({"bench", (source_dir() / "scenes" / (name + ".toml")).string(), "--size",
                                       size, "--frames", "1", "--warmup", "0", "--json", "--strict"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // --strict: no NaN/Inf pixel (exit 1). And bench checks the bounds
  // (render/bounds_check.h): a shipped scene's hold its map.
  EXPECT_EQ(r.err.find("warning: map() is negative on the [bounds] surface"), std::string::npos) << r.err;
  const nlohmann::json cost = nlohmann::json::parse(r.out).at("cost");
  const double steps = cost.at("primary_steps").at("mean").get<double>();
  const double cap = cost.at("step_cap_fraction").get<double>();
  EXPECT_LE(steps, *max_steps) << name << ": mean primary steps per pixel went up";
  EXPECT_LE(cap, *max_cap) << name << ": more pixels hit the step cap";
  // A bound far above the measurement protects nothing: keep them within
  // ~25% (they are set ~10% above), so an improvement gets its bound lowered.
  EXPECT_GE(steps, *max_steps / 1.25) << name << ": cheaper now; lower the bound in tests/cost/bounds.toml";
}

// Every shipped scene, globbed: a new scene cannot slip in without bounds.
std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(source_dir() / "scenes"))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Cost, ::testing::ValuesIn(scene_names()));

}  // namespace
}  // namespace ms::test
