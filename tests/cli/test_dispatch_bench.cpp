// bench and sweep --dispatch: each bench row names the dispatch
// that drew it, and the counting pass's step counts are the same with
// either; auto records what it resolved to; what compute cannot run is
// refused in one line. A sweep with compute gives the fragment sweep's
// rows: step counts equal, errors within what 1e-5 per channel allows.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json bench(const TempDir& dir, const std::string& scene, const std::string& dispatch) {
  const RunResult r = run_marchstudio({"bench", (source_dir() / "scenes" / (scene + ".toml")).string(), "--size",
                                       "64x36", "--frames", "2", "--warmup", "1", "--dispatch", dispatch, "--json"},
                                      dir.path(), "XDG_CACHE_HOME='" + (dir / "cache").string() + "' ");
  EXPECT_EQ(r.exit_code, 0) << scene << " " << dispatch << ": " << r.err;
  return r.exit_code == 0 ? json::parse(r.out) : json();
}

TEST(DispatchBench, RowsNameTheDispatchAndCountTheSameSteps) {
  TempDir dir;
  for (const std::string scene : {"seed", "stilllife", "envlight"}) {
    const json f = bench(dir, scene, "fragment"), c = bench(dir, scene, "compute");
    ASSERT_FALSE(f.is_null() || c.is_null());
    EXPECT_EQ(f["settings"]["dispatch"], "fragment");
    EXPECT_EQ(c["settings"]["dispatch"], "compute");
    EXPECT_GT(f["cost"]["sdf_evals"]["mean"].get<double>(), 0.0) << scene;
    EXPECT_EQ(f["cost"], c["cost"]) << scene;  // every count, mean, p99 and max
  }
  const json a = bench(dir, "seed", "auto");
  ASSERT_FALSE(a.is_null());
  const std::string chose = a["settings"]["dispatch"];
  EXPECT_TRUE(chose == "fragment" || chose == "compute") << chose;
  EXPECT_TRUE(fs::exists(dir / "cache" / "marchstudio" / "dispatch"));
}

TEST(DispatchBench, RefusesWhatComputeCannotRunInOneLine) {
  TempDir dir;
  write_file(dir / "d.glsl", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(dFdy(f.y));\n}\n");
  const RunResult r = run_marchstudio({"bench", "d.glsl", "--size", "16x16", "--dispatch", "compute"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("d.glsl:2"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

json sweep(const TempDir& dir, const std::string& dispatch) {
  const fs::path out = dir / dispatch;
  const RunResult r = run_marchstudio({"sweep", (source_dir() / "scenes" / "seed.toml").string(), "--size", "48x27",
                                       "--frames", "1", "--rounds", "1", "--warmup", "0", "--ref-spp", "2", "--only",
                                       "textbook,fast,balanced", "--dispatch", dispatch, "-q", "-o", out.string()},
                                      dir.path(), "XDG_CACHE_HOME='" + (dir / "cache").string() + "' ");
  EXPECT_EQ(r.exit_code, 0) << dispatch << ": " << r.err;
  return r.exit_code == 0 ? json::parse(read_file(out / "seed.sweep.json")) : json();
}

TEST(DispatchSweep, ComputeRowsEqualFragmentRows) {
  TempDir dir;
  const json f = sweep(dir, "fragment"), c = sweep(dir, "compute");
  ASSERT_FALSE(f.is_null() || c.is_null());
  EXPECT_EQ(f["settings"]["dispatch"], "fragment");
  EXPECT_EQ(c["settings"]["dispatch"], "compute");
  ASSERT_EQ(f["rows"].size(), 3u);
  ASSERT_EQ(c["rows"].size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const json& a = f["rows"][i];
    const json& b = c["rows"][i];
    EXPECT_EQ(a["name"], b["name"]);
    EXPECT_EQ(a["cost"], b["cost"]) << a["name"];
    for (const char* ref : {"same_spp", "supersampled"}) {
      EXPECT_NEAR(a["error"][ref]["mae"].get<double>(), b["error"][ref]["mae"].get<double>(), 1e-5) << a["name"];
    }
    EXPECT_EQ(a["error"]["same_spp"]["misclassified"], b["error"]["same_spp"]["misclassified"]) << a["name"];
  }
}

TEST(DispatchTestCmd, AutoIsRefusedBeforeAnyCase) {
  const RunResult r = run_marchstudio(
      {"test", (source_dir() / "tests" / "cost" / "suite.toml").string(), "--dispatch", "auto"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("a suite checks one dispatch at a time"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace ms::test
