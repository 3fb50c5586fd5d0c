// The [bounds] check on the paths a farm runs (pipeline/bounds_report.h): a
// plain `render`, a --jobs batch and a --frames sequence warn when map()
// crosses the bounds, once per scene; --strict makes it exit 1 with no file.
#include <gtest/gtest.h>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

std::string data(const std::string& name) { return (fs::path(MARCH_TEST_DATA) / "bounds" / name).string(); }

const char* kWarning = "warning: map() is negative on the [bounds] surface";

int count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

TEST(BoundsFarm, EveryRenderWarnsAndStrictWritesNothing) {
  TempDir dir;
  RunResult r = run_marchstudio({"render", data("ball_big.toml"), "-o", (dir / "a.png").string(), "--size", "32x18"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count(r.err, kWarning), 1) << r.err;
  EXPECT_NE(r.err.find("--strict makes this an error"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "a.png")) << "a warning, not an error";
  r = run_marchstudio({"render", data("ball_big.toml"), "-o", (dir / "b.png").string(), "--size", "32x18", "--strict"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("--strict"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ball_big.toml"), std::string::npos) << r.err;
  EXPECT_EQ(count(r.err, "\n"), 1) << "one line: " << r.err;
  EXPECT_FALSE(fs::exists(dir / "b.png"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.png"}) << "no temporary left";
  // A scene that fits: no word, and --strict renders it.
  r = run_marchstudio({"render", data("ball.toml"), "-o", (dir / "c.png").string(), "--size", "32x18", "--strict"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find(kWarning), std::string::npos) << r.err;
}

TEST(BoundsFarm, ABatchWarnsOncePerScene) {
  TempDir dir;
  write_file(dir / "jobs.jsonl",
             "{\"scene\": \"" + data("ball_big.toml") + "\", \"output\": \"a.png\"}\n"
             "{\"scene\": \"" + data("ball_big.toml") + "\", \"output\": \"b.png\", \"time\": 1.0}\n"
             "{\"scene\": \"" + data("ball.toml") + "\", \"output\": \"c.png\"}\n"
             "{\"scene\": \"" + data("ball_big.toml") + "\", \"output\": \"d.png\", \"strict\": true}\n");
  const RunResult r = run_marchstudio({"render", "--jobs", (dir / "jobs.jsonl").string(), "--size", "32x18"});
  EXPECT_EQ(r.exit_code, 1) << "the strict job fails alone: " << r.err;
  EXPECT_EQ(count(r.err, kWarning), 1) << r.err;
  for (const char* f : {"a.png", "b.png", "c.png"}) EXPECT_TRUE(fs::exists(dir / f)) << f << "\n" << r.err;
  EXPECT_FALSE(fs::exists(dir / "d.png")) << r.err;
  EXPECT_NE(r.err.find("jobs.jsonl:4: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 of 4 jobs failed"), std::string::npos) << r.err;
}

TEST(BoundsFarm, ASequenceWarnsOnceAndStrictStopsBeforeItsFrame) {
  TempDir dir;
  RunResult r = run_marchstudio({"render", data("ball_big.toml"), "--frames", "0..2", "-o",
                                 (dir / "f_%02d.png").string(), "--size", "32x18"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count(r.err, kWarning), 1) << r.err;
  EXPECT_EQ(count_files(dir.path(), "f_"), 3);
  r = run_marchstudio({"render", data("ball_big.toml"), "--frames", "0..2", "-o", (dir / "g_%02d.png").string(),
                       "--size", "32x18", "--strict"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("--strict"), std::string::npos) << r.err;
  EXPECT_EQ(count_files(dir.path(), "g_"), 0) << r.err;
}

}  // namespace
}  // namespace ms::test
