// A sequence of a shader with buffers never stalls on its checkpoints
// (io/checkpoint.h, pipeline/sequence_state.h): a corrupt one is passed over
// with a warning and the frames replay (exit 0, the same frames as a clean
// run); one copied over another frame's is not trusted (each carries its
// frame's fingerprint); a checkpoint's temporary left by a killed run is
// removed by the rerun.
#include <gtest/gtest.h>

#include <string>

#include "io/atomic_file.h"
#include "io/image_io.h"
#include "chaos_passes.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

struct Project {
  TempDir dir;
  Project() { write_chaos_project(dir, 3, 32, 24); }
  RunResult frames(const std::string& range) {
    return run_marchstudio({"render", "s.toml", "--frames", range, "--fps", "30", "-o", "f_%d.exr"}, dir.path(),
                           "timeout 120 ");
  }
  // The checkpoint of frame f (the one of this shader's key), or empty.
  fs::path checkpoint(int f) const {
    const std::string prefix = ".f_" + std::to_string(f) + ".exr.";
    for (const std::string& name : dir.entries())
      if (name.rfind(prefix, 0) == 0 && name.size() > 10 && name.compare(name.size() - 10, 10, ".state.exr") == 0 &&
          name.find(".cube.") == std::string::npos)
        return dir / name;
    return {};
  }
};

// Frames 0..5 of an uninterrupted run, to compare with.
std::vector<Image> reference() {
  Project p;
  const RunResult r = p.frames("0..5");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::vector<Image> out;
  for (int f = 0; f <= 5; ++f) out.push_back(read_image(p.dir / ("f_" + std::to_string(f) + ".exr")));
  return out;
}

void expect_frames(const Project& p, const std::vector<Image>& ref) {
  ASSERT_EQ(ref.size(), 6u);
  for (int f = 0; f <= 5; ++f)
    EXPECT_EQ(read_image(p.dir / ("f_" + std::to_string(f) + ".exr")).pixels, ref[static_cast<size_t>(f)].pixels)
        << "frame " << f;
}

TEST(CheckpointResume, ACorruptCheckpointIsReplayedPastWithAWarning) {
  const std::vector<Image> ref = reference();
  Project p;
  ASSERT_EQ(p.frames("0..3").exit_code, 0);
  const fs::path cp = p.checkpoint(3);
  ASSERT_FALSE(cp.empty()) << "no checkpoint for frame 3";
  const std::string bytes = read_file(cp);
  write_file(cp, bytes.substr(0, bytes.size() / 2));  // cut, as a copy or a full disk would leave it
  const RunResult r = p.frames("0..5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: the checkpoint of frame 3 is not used (unreadable"), std::string::npos) << r.err;
  expect_frames(p, ref);
  // And the next rerun trusts the fresh checkpoints again: nothing to do.
  const RunResult again = p.frames("0..5");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.err.find("warning"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("6 already complete, 0 to render"), std::string::npos) << again.err;
}

TEST(CheckpointResume, ACheckpointCopiedOverAnotherFramesIsNotTrusted) {
  const std::vector<Image> ref = reference();
  Project p;
  ASSERT_EQ(p.frames("0..1").exit_code, 0);
  const fs::path of1 = p.checkpoint(1);
  ASSERT_FALSE(of1.empty());
  const std::string frame1_state = read_file(of1);
  ASSERT_EQ(p.frames("0..3").exit_code, 0);
  const fs::path of3 = p.checkpoint(3);
  ASSERT_FALSE(of3.empty());
  write_file(of3, frame1_state);  // frame 1's state under frame 3's name
  const RunResult r = p.frames("0..5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("the checkpoint of frame 3 is not used (it was made for another frame or run)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("resuming after frame 3"), std::string::npos) << r.err;
  expect_frames(p, ref);
}

TEST(CheckpointResume, AKilledRunsCheckpointTemporaryIsRemoved) {
  Project p;
  ASSERT_EQ(p.frames("0..3").exit_code, 0);
  const fs::path of3 = p.checkpoint(3);
  ASSERT_FALSE(of3.empty());
  // SIGKILL while frame 4's checkpoint was written: its temporary (by a pid
  // that is gone), beside a complete frame 4 made later by nobody.
  const std::string key_part = of3.filename().string().substr(std::string(".f_3.exr").size());
  const fs::path temp = temp_path_for(p.dir / (".f_4.exr" + key_part), 999999999);
  write_file(temp, "half a checkpoint");
  const RunResult r = p.frames("0..5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(temp)) << r.err;
  EXPECT_NE(r.err.find("removed " + temp.filename().string() + ", left by an interrupted run"), std::string::npos) << r.err;
  for (const std::string& name : p.dir.entries()) EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
}

}  // namespace
}  // namespace ms::test
