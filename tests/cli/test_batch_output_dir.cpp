// `render --jobs FILE --output-dir DIR` (docs/usage.md#batches): a job's
// relative "output" is under DIR, so the directory is never silently
// unused; an absolute one is kept; without --output-dir a relative output
// is under the job file's directory, as the other paths of a line are.
#include <gtest/gtest.h>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

std::string scene() { return (fs::path(MARCH_TEST_DATA) / "bounds" / "ball.toml").string(); }

TEST(BatchOutputDir, IsTheBaseOfRelativeJobOutputs) {
  TempDir dir;
  fs::create_directories(dir / "jobs");
  write_file(dir / "jobs" / "jobs.jsonl",
             "{\"scene\": \"" + scene() + "\", \"output\": \"x.png\"}\n"
             "{\"scene\": \"" + scene() + "\", \"output\": \"sub/y.png\", \"time\": 0.5}\n"
             "{\"scene\": \"" + scene() + "\", \"output\": \"" + (dir / "abs.png").string() + "\", \"time\": 1.0}\n");
  RunResult r = run_marchstudio({"render", "--jobs", (dir / "jobs" / "jobs.jsonl").string(), "--size", "32x18",
                                 "--output-dir", (dir / "stills").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "stills" / "x.png")) << r.out;
  EXPECT_TRUE(fs::exists(dir / "stills" / "sub" / "y.png")) << r.out;
  EXPECT_TRUE(fs::exists(dir / "abs.png")) << r.out;
  EXPECT_FALSE(fs::exists(dir / "jobs" / "x.png")) << "--output-dir was not used";
  EXPECT_NE(r.out.find((dir / "stills" / "x.png").string()), std::string::npos) << "the path printed is where it went";
  // Without --output-dir: beside the job file.
  r = run_marchstudio({"render", "--jobs", (dir / "jobs" / "jobs.jsonl").string(), "--size", "32x18"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "jobs" / "x.png"));
  EXPECT_TRUE(fs::exists(dir / "jobs" / "sub" / "y.png"));
}

}  // namespace
}  // namespace ms::test
