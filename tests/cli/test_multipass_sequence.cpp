// Sequences of a shader with buffers carry the buffers from
// frame to frame; a run killed with SIGKILL resumes from its checkpoint
// with frames bit-identical to an uninterrupted run's; a chunk shard
// replays the frames before its own; stride shards are refused.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include "io/image_io.h"
#include "chaos_passes.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

void write_project(const TempDir& dir, int loops) { write_chaos_project(dir, loops, 64, 48); }

std::vector<std::string> frames_args(const std::string& range, const std::string& out) {
  return {"render", "s.toml", "--frames", range, "--fps", "30", "-o", out};
}

TEST(MultipassSequence, CarriesStateAndEqualsStills) {
  TempDir dir;
  write_project(dir, 3);
  const RunResult r = run_marchstudio(frames_args("0..5", "f_%d.exr"), dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Frame 5 of the sequence is the still at its time: frames 0..5 replayed.
  const RunResult s = run_marchstudio({"render", "s.toml", "--time", "0.1666666667", "--fps", "30", "-o", "still.exr"},
                                      dir.path());
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const Image seq = read_image(dir / "f_5.exr"), still = read_image(dir / "still.exr");
  EXPECT_EQ(seq.pixels, still.pixels);
  EXPECT_FLOAT_EQ(seq.at(0, 0, 1), 6.0f / 64.0f);  // six frames were added to the count
}

TEST(MultipassSequence, ResumesAfterSigkillBitForBit) {
  TempDir whole, killed;
  write_project(whole, 20000);
  write_project(killed, 20000);
  const RunResult ref = run_marchstudio(frames_args("0..23", "f_%02d.exr"), whole.path());
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  {
    BackgroundProcess p([&] {
      std::vector<std::string> a = {MARCH_BIN};
      for (const std::string& s : frames_args("0..23", "f_%02d.exr")) a.push_back(s);
      return a;
    }(), killed / "out.txt", killed / "err.txt", killed.path());
    ASSERT_TRUE(wait_until([&] { return fs::exists(killed / "f_06.exr"); }, 60)) << read_file(killed / "err.txt");
    p.signal(SIGKILL);
    p.wait_exit(10);
  }
  ASSERT_FALSE(fs::exists(killed / "f_23.exr")) << "the run finished before it was killed";
  const RunResult resumed = run_marchstudio(frames_args("0..23", "f_%02d.exr"), killed.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("from its checkpoint"), std::string::npos) << resumed.err;
  for (int f = 0; f <= 23; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "f_%02d.exr", f);
    EXPECT_EQ(read_image(whole / name).pixels, read_image(killed / name).pixels) << name;
  }
}

TEST(MultipassSequence, ChunkShardsReplayAndStrideShardsAreRefused) {
  TempDir whole, shard;
  write_project(whole, 3);
  write_project(shard, 3);
  ASSERT_EQ(run_marchstudio(frames_args("0..9", "f_%d.exr"), whole.path()).exit_code, 0);
  std::vector<std::string> a = frames_args("0..9", "f_%d.exr");
  a.insert(a.end(), {"--shard", "1/2", "--shard-mode", "chunk"});
  const RunResult r = run_marchstudio(a, shard.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("replaying frames 0..4 first"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(shard / "f_4.exr"));
  for (int f = 5; f <= 9; ++f)
    EXPECT_EQ(read_image(whole / ("f_" + std::to_string(f) + ".exr")).pixels,
              read_image(shard / ("f_" + std::to_string(f) + ".exr")).pixels)
        << f;
  std::vector<std::string> b = frames_args("0..9", "g_%d.exr");
  b.insert(b.end(), {"--shard", "0/2"});
  const RunResult s = run_marchstudio(b, shard.path());
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("use --shard-mode chunk"), std::string::npos) << s.err;
}

}  // namespace
}  // namespace ms::test
