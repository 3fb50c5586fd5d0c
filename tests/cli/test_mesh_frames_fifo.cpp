// `mesh --frames` resumes by reading each frame's stamp and hashing its
// files (io/file_stamp.h). A FIFO in place of a frame, a part or a stamp
// is not a complete frame, found without waiting for a writer: the run
// ends promptly, meshing the frame again (written through the FIFO when a
// process reads it, a clear error when none does).
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

void write_scene(const TempDir& dir) {
  write_file(dir / "ball.glsl", "vec2 map(vec3 p) {\n  return vec2(length(p) - (0.4 + 0.2 * uTime), MAT_PART);\n}\n");
  write_file(dir / "ball.toml",
             "[scene]\nname = \"ball\"\nmap = \"ball.glsl\"\n\n[bounds]\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, "
             "1.0]\n\n[[materials]]\nname = \"part\"\ncolor = [0.7, 0.7, 0.75]\n");
}

// Bounded: a run that blocks on a FIFO ends with 124, not a hung test.
RunResult mesh_frames(const TempDir& dir, const std::string& before = {}) {
  return run_marchstudio({"mesh", "ball.toml", "--frames", "0..2", "--fps", "1", "--resolution", "16", "-o",
                          "f_%02d.obj"},
                         dir.path(), before + "timeout 60 ");
}

void make_fifo(const fs::path& p) {
  fs::remove(p);
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
}

TEST(MeshFramesFifo, AFifoInPlaceOfAStampedFrameIsNotWaitedOn) {
  TempDir dir;
  write_scene(dir);
  ASSERT_EQ(mesh_frames(dir).exit_code, 0);
  const std::string frame1 = read_file(dir / "f_01.obj");

  // Frame 1's stamp still lists the file: reading it must not block.
  make_fifo(dir / "f_01.obj");
  RunResult r = mesh_frames(dir);
  EXPECT_EQ(r.exit_code, 3) << "124 is a hang: " << r.err;
  EXPECT_NE(r.err.find("frame 1: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("f_01.obj is a FIFO (named pipe), not a regular file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no process is reading it"), std::string::npos) << r.err;
  EXPECT_EQ(count_of(r.err, " skipped: "), 2) << r.err;

  // With a reader, the frame goes through the FIFO, and is not stamped.
  const std::string d = dir.path().string();
  r = mesh_frames(dir, "timeout 60 cat '" + d + "/f_01.obj' > '" + d + "/got.obj' 2>/dev/null & sleep 0.3; cd '" + d +
                           "' && ");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("frame 1 meshed in "), std::string::npos) << r.err;
  // The reader may still be draining the pipe when marchstudio is done.
  for (int i = 0; i < 100 && read_file(dir / "got.obj") != frame1; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(read_file(dir / "got.obj") == frame1) << "the frame, whole, through the FIFO";
  EXPECT_TRUE(fs::is_fifo(dir / "f_01.obj"));
  EXPECT_FALSE(fs::exists(dir / ".f_01.obj.stamp.json"));

  // A FIFO in place of a part (the .mtl) of a stamped frame.
  fs::remove(dir / "f_01.obj");
  ASSERT_EQ(mesh_frames(dir).exit_code, 0);
  make_fifo(dir / "f_02.mtl");
  r = mesh_frames(dir);
  EXPECT_EQ(r.exit_code, 3) << "124 is a hang: " << r.err;
  EXPECT_NE(r.err.find("f_02.mtl is a FIFO"), std::string::npos) << r.err;
}

TEST(MeshFramesFifo, AFifoInPlaceOfAStampIsAnUnmarkedFrameMeshedAgain) {
  TempDir dir;
  write_scene(dir);
  ASSERT_EQ(mesh_frames(dir).exit_code, 0);
  const std::string frame0 = read_file(dir / "f_00.obj");
  make_fifo(dir / ".f_00.obj.stamp.json");
  const RunResult r = mesh_frames(dir);
  EXPECT_EQ(r.exit_code, 0) << "124 is a hang: " << r.err;
  EXPECT_NE(r.err.find("its stamp .f_00.obj.stamp.json is a FIFO"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frame 0 meshed in "), std::string::npos) << r.err;
  EXPECT_EQ(count_of(r.err, " skipped: "), 2) << r.err;
  EXPECT_TRUE(read_file(dir / "f_00.obj") == frame0);
  EXPECT_TRUE(fs::is_regular_file(dir / ".f_00.obj.stamp.json")) << "the stamp is written again";
}

}  // namespace
}  // namespace ms::test
