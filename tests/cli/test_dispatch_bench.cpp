// bench --dispatch (issue 18): each row names the dispatch that drew it, and
// the counting pass's step counts are the same with either; auto records
// what it resolved to; what compute cannot run is refused in one line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace ms::test
