// `marchstudio mesh` under SIGTERM and Ctrl-C while it writes: no
// temporary is left, nor the .mtl of an OBJ that never landed (exit 143 /
// 130), in every mesh format; and a rerun removes the temporaries a killed
// run (a pid that is gone) left beside its files, never a live one's.
// tests/shims/slow_temp.c holds each temporary's creation so the signal
// lands while it exists.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "run.h"
#include "signal_util.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

fs::path ball(const TempDir& dir) {
  write_file(dir / "ball.glsl", "vec2 map(vec3 p) {\n  return vec2(length(p) - 0.5, MAT_PART);\n}\n");
  write_file(dir / "ball.toml",
             "[scene]\nname = \"ball\"\nmap = \"ball.glsl\"\n\n[bounds]\nmin = [-1, -1, -1]\nmax = [1, 1, 1]\n\n"
             "[[materials]]\nname = \"part\"\ncolor = [0.7, 0.7, 0.75]\n");
  return dir / "ball.toml";
}

// Meshes the ball to `output` with each temporary held 4 s after it is
// made: nothing is left but the scene and the logs (no mesh, no .mtl).
void expect_signal_leaves_nothing(const std::string& output, const std::string& temp_prefix, int sig) {
  TempDir dir;
  const fs::path scene = ball(dir);
  expect_signal_leaves_no_temp(dir, {"mesh", scene.string(), "--resolution", "16", "-o", output}, temp_prefix, sig,
                               {"ball.glsl", "ball.toml"}, 4000);
}

TEST(MeshSignals, SigtermWhileAnObjIsWrittenLeavesNeitherItsTemporaryNorItsMtl) {
  // The .mtl lands first; the OBJ that names it never does.
  expect_signal_leaves_nothing("part.obj", ".part.obj.tmp", SIGTERM);
}

TEST(MeshSignals, CtrlCWhileEachOtherFormatIsWrittenLeavesNoTemporary) {
  for (const char* ext : {"ply", "glb", "stl"}) {
    SCOPED_TRACE(ext);
    expect_signal_leaves_nothing(std::string("part.") + ext, std::string(".part.") + ext + ".tmp", SIGINT);
  }
}

TEST(MeshSignals, AnObjThatWasThereKeepsItsMtl) {
  TempDir dir;
  const fs::path scene = ball(dir);
  ASSERT_EQ(run_marchstudio({"mesh", scene.string(), "--resolution", "16", "-o", "part.obj"}, dir.path()).exit_code, 0);
  BackgroundProcess p({"env", "LD_PRELOAD=" + slow_temp_preload(), "SLOW_TEMP_MS=4000", MARCH_BIN, "mesh", scene.string(),
                       "--resolution", "16", "-o", "part.obj"},
                      dir / "out.txt", dir / "err.txt", dir.path());
  const auto temp_exists = [&] {
    for (const std::string& name : dir.entries())
      if (name.rfind(".part.obj.tmp", 0) == 0) return true;
    return false;
  };
  ASSERT_TRUE(wait_until(temp_exists, 90)) << read_file(dir / "err.txt");
  p.signal(SIGTERM);
  EXPECT_EQ(p.wait_exit(20), 128 + SIGTERM) << read_file(dir / "err.txt");
  EXPECT_TRUE(fs::exists(dir / "part.obj"));
  EXPECT_TRUE(fs::exists(dir / "part.mtl")) << "the OBJ on disk names it";
  EXPECT_FALSE(temp_exists());
}

TEST(MeshSignals, ARerunRemovesADeadRunsTemporariesButNotALiveOnes) {
  TempDir dir;
  const fs::path scene = ball(dir);
  const std::string dead_obj = ".part.obj.tmp999999999", dead_mtl = ".part.mtl.tmp999999999";  // no such pid
  const std::string live = ".part.obj.tmp" + std::to_string(::getpid());  // this test: alive
  for (const std::string& name : {dead_obj, dead_mtl, live}) write_file(dir / name, "half a mesh");
  const RunResult r = run_marchstudio({"mesh", scene.string(), "--resolution", "16", "-o", "part.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& dead : {dead_obj, dead_mtl}) {
    EXPECT_NE(r.err.find("marchstudio: removed " + dead + ", left by an interrupted run"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / dead));
  }
  EXPECT_TRUE(fs::exists(dir / live)) << "another process's write in progress";
  // The same for each frame of a sequence.
  const std::string dead_frame = ".f_01.mtl.tmp999999999";
  write_file(dir / dead_frame, "half a mesh");
  const RunResult s =
      run_marchstudio({"mesh", scene.string(), "--resolution", "16", "--frames", "0..1", "-o", "f_%02d.obj"},
                      dir.path());
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_FALSE(fs::exists(dir / dead_frame)) << s.err;
}

}  // namespace
}  // namespace ms::test
