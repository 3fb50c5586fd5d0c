// One signal scope for every still's write (io/temp_cleanup.h): SIGTERM or
// Ctrl-C while an ordinary still or a --jobs batch writes its image leaves
// no temporary (exit 143 / 130), and a rerun removes the temporary a
// killed run (a pid that is gone) left beside its output, never one of a
// live process. tests/shims/slow_temp.c holds each temporary's creation so
// the signal lands while it exists.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "run.h"
#include "signal_util.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::string kSeed = (source_dir() / "scenes/seed.toml").string();

TEST(StillSignals, SigtermWhileAStillIsWrittenLeavesNoTemporary) {
  TempDir dir;
  expect_signal_leaves_no_temp(dir, {"render", kSeed, "--size", "64x36", "-o", "still.png"}, ".still.png.tmp", SIGTERM,
                               {}, 30000);
}

TEST(StillSignals, CtrlCWhileABatchWritesLeavesNoTemporary) {
  TempDir dir;
  write_file(dir / "jobs.jsonl", "{\"scene\": \"" + kSeed + "\", \"output\": \"a.png\"}\n{\"scene\": \"" + kSeed +
                                     "\", \"output\": \"b.png\"}\n");
  expect_signal_leaves_no_temp(dir, {"render", "--jobs", "jobs.jsonl", "--size", "48x27"}, ".a.png.tmp", SIGINT,
                               {"jobs.jsonl"}, 30000);
}

TEST(StillSignals, ARerunRemovesADeadRunsTemporaryButNotALiveOnes) {
  TempDir dir;
  const std::string dead = ".out.png.tmp999999999";  // above any pid_max: no such process
  const std::string live = ".out.png.tmp" + std::to_string(::getpid());  // this test: alive
  const std::string other = ".other.png.tmp999999999";  // not this run's output
  for (const std::string& name : {dead, live, other}) write_file(dir / name, "half an image");
  const RunResult r = run_marchstudio({"render", kSeed, "--size", "32x18", "-o", "out.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("marchstudio: removed " + dead + ", left by an interrupted run"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / dead));
  EXPECT_TRUE(fs::exists(dir / live)) << "another process's write in progress";
  EXPECT_TRUE(fs::exists(dir / other));
  EXPECT_TRUE(fs::exists(dir / "out.png"));
  // The same in a batch, for each job's output.
  write_file(dir / dead, "half an image");
  write_file(dir / "jobs.jsonl", "{\"scene\": \"" + kSeed + "\", \"output\": \"out.png\"}\n");
  const RunResult b = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "32x18"}, dir.path());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_FALSE(fs::exists(dir / dead)) << b.err;
}

}  // namespace
}  // namespace ms::test
