// `marchstudio mesh`'s guards through the real binary: a --voxel under the
// cell limit is refused at once (it once looped forever), flags that make
// no sense are one line each, a field that is NaN is said (an error under
// --strict, or when nothing else is left), the memory budget stops a grid
// whose surface would not fit, a long --frames range holds numbers, not
// paths, and every file written is printed on stdout.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <thread>
#include <regex>
#include <string>
#include <vector>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A scene of one map() returning `body`, material "part", in a 2-unit box.
fs::path scene(const TempDir& dir, const std::string& name, const std::string& body) {
  write_file(dir / (name + ".glsl"), "vec2 map(vec3 p) {\n" + body + "\n}\n");
  write_file(dir / (name + ".toml"), "[scene]\nname = \"" + name + "\"\nmap = \"" + name +
                                          ".glsl\"\n\n[bounds]\nmin = [-1, -1, -1]\nmax = [1, 1, 1]\n\n"
                                          "[[materials]]\nname = \"part\"\ncolor = [0.7, 0.7, 0.75]\n");
  return dir / (name + ".toml");
}

const std::string kSphere = "  return vec2(length(p) - 0.5, MAT_PART);";
// NaN on every point (sqrt of a negative number).
const std::string kNaN = "  return vec2(sqrt(-1.0 - abs(p.x)), MAT_PART);";
// NaN on the +x half, a sphere elsewhere.
const std::string kNaNHalf =
    "  float bad = sqrt(-1.0 - abs(p.y));\n  return vec2(p.x > 0.013 ? bad : length(p) - 0.5, MAT_PART);";

std::vector<std::string> mesh(const fs::path& f, std::vector<std::string> more) {
  std::vector<std::string> args = {"mesh", f.string()};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Files in `dir` other than the scene's own.
std::vector<std::string> written_in(const TempDir& dir) {
  std::vector<std::string> out;
  for (const std::string& name : dir.entries())
    if (name.find(".toml") == std::string::npos && name.find(".glsl") == std::string::npos) out.push_back(name);
  return out;
}

// One line on stderr naming `flag`, exit 2, nothing written, well before
// the 60 s the shell gives it.
void expect_refused(const TempDir& dir, const std::vector<std::string>& args, const std::string& flag) {
  const RunResult r = run_marchstudio(args, dir.path(), "timeout 60 ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
  EXPECT_LT(r.err.size(), 300u) << "no number printed in full: " << r.err;
  EXPECT_TRUE(written_in(dir).empty()) << r.err;
}

TEST(MeshGuards, AVoxelUnderTheCellLimitIsRefusedAtOnce) {
  TempDir dir;
  const fs::path f = scene(dir, "ball", kSphere);
  // 1e-9 overflowed the cell count and never finished; 1e-300 was "no surface".
  for (const char* voxel : {"1e-9", "1e-300", "1e-5"}) {
    SCOPED_TRACE(voxel);
    expect_refused(dir, mesh(f, {"--voxel", voxel, "-o", "out.obj"}), "--voxel");
    const RunResult r = run_marchstudio(mesh(f, {"--voxel", voxel, "-o", "out.obj"}), dir.path(), "timeout 60 ");
    EXPECT_NE(r.err.find("over the limit of 4096"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("give --voxel 0.000488281 or more"), std::string::npos) << r.err;
  }
}

TEST(MeshGuards, FlagsThatMakeNoSenseAreOneLineEach) {
  TempDir dir;
  const fs::path f = scene(dir, "ball", kSphere);
  expect_refused(dir, mesh(f, {"--voxel", "nan", "-o", "out.obj"}), "--voxel");
  expect_refused(dir, mesh(f, {"--voxel", "0", "-o", "out.obj"}), "--voxel");
  expect_refused(dir, mesh(f, {"--timeout", "-1", "-o", "out.obj"}), "--timeout");
  expect_refused(dir, mesh(f, {"-o", ""}), "--output");
  expect_refused(dir, mesh(f, {"--time", "nan", "-o", "out.obj"}), "--time");
  expect_refused(dir, mesh(f, {"--time", "inf", "-o", "out.obj"}), "--time");
  expect_refused(dir, mesh(f, {"--frames", "0..3", "--fps", "1e-300", "-o", "f_%04d.obj"}), "--fps");
}

TEST(MeshGuards, AFieldThatIsNaNEverywhereIsNotMeshed) {
  TempDir dir;
  const fs::path f = scene(dir, "nan", kNaN);
  // It was the box's shell, "watertight", exit 0.
  const RunResult r = run_marchstudio(mesh(f, {"--resolution", "16", "-o", "out.ply"}), dir.path(), "timeout 120 ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("map\\(\\) is NaN or Inf at [1-9][0-9]* of [1-9][0-9]* samples")))
      << r.err;
  EXPECT_TRUE(written_in(dir).empty()) << r.err;
}

TEST(MeshGuards, NaNSamplesAreAWarningOrUnderStrictAnError) {
  TempDir dir;
  const fs::path f = scene(dir, "half", kNaNHalf);
  const std::regex count("[1-9][0-9]* of [1-9][0-9]* samples of map\\(\\) have NaN/Inf values");
  const RunResult warned = run_marchstudio(mesh(f, {"--resolution", "24", "-o", "w.ply"}), dir.path());
  EXPECT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_TRUE(std::regex_search(warned.err, count)) << warned.err;
  EXPECT_NE(warned.err.find("warning"), std::string::npos) << warned.err;
  EXPECT_TRUE(fs::exists(dir / "w.ply"));
  const RunResult strict = run_marchstudio(mesh(f, {"--resolution", "24", "--strict", "-o", "s.ply"}), dir.path());
  EXPECT_EQ(strict.exit_code, 1) << strict.err;
  EXPECT_TRUE(std::regex_search(strict.err, count)) << strict.err;
  EXPECT_NE(strict.err.find("--strict"), std::string::npos) << strict.err;
  EXPECT_NE(strict.err.find("nothing written"), std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(dir / "s.ply"));
  // A finite field says nothing of the kind.
  const RunResult clean = run_marchstudio(mesh(scene(dir, "ball", kSphere), {"--resolution", "16", "--strict",
                                                                             "-o", "c.ply"}),
                                          dir.path());
  EXPECT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(clean.err.find("NaN"), std::string::npos) << clean.err;
}

TEST(MeshGuards, ASurfaceOverTheMemoryBudgetIsRefusedBeforeItIsSampled) {
  TempDir dir;
  // A gyroid of period 0.2 fills the box with surface: at 4096 cells it
  // would need far more than any budget (it grew until the OOM killer).
  const fs::path f = scene(dir, "gyroid",
                           "  vec3 q = p * 31.4159;\n"
                           "  float g = dot(sin(q), cos(q.yzx)) / 31.4159 / 1.8;\n"
                           "  return vec2(g, MAT_PART);");
  const RunResult r =
      run_marchstudio(mesh(f, {"--resolution", "4096", "-o", "g.ply"}), dir.path(), "timeout 120 ");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.err, m, std::regex("the mesh needs about [0-9.]+ GiB, over the [0-9.]+ [GM]iB memory budget \\(give "
                           "--resolution ([0-9]+) or less")))
      << r.err;
  EXPECT_GE(std::stoi(m[1]), 8);
  EXPECT_LT(std::stoi(m[1]), 4096);
  EXPECT_TRUE(written_in(dir).empty()) << r.err;
}

// The resident peak (VmHWM, KiB) of `mesh --frames 0..last` once its first
// frame is written, the process then killed.
long peak_at_first_frame(const TempDir& dir, const fs::path& scene, int last) {
  const std::string log = "frames" + std::to_string(last) + ".log";
  const pid_t pid = spawn_marchstudio({"mesh", scene.string(), "--resolution", "8", "--frames",
                                       "0.." + std::to_string(last), "-o", "f" + std::to_string(last) + "_%08d.ply"},
                                      dir.path(), log);
  const std::string first = "f" + std::to_string(last) + "_00000000.ply";
  long peak = -1;
  for (int i = 0; i < 6000 && peak < 0; ++i) {
    if (read_file(dir / log).find(first + "\n") != std::string::npos) {
      std::ifstream status("/proc/" + std::to_string(pid) + "/status");
      for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) peak = std::stol(line.substr(6));
    }
    int st = 0;
    if (peak < 0 && waitpid(pid, &st, WNOHANG) == pid) {
      ADD_FAILURE() << "it ended before its first frame: " << read_file(dir / log);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  return peak;
}

TEST(MeshGuards, AFrameRangeCostsItsNumbersNotItsPaths) {
  TempDir dir;
  const fs::path f = scene(dir, "ball", kSphere);
  // A million frames held each frame's paths (about 64 bytes a frame:
  // 7.3 GB for 10^8); their numbers are 4 bytes. The few are a thousand,
  // not two: two frames can end before their peak is read.
  const long few = peak_at_first_frame(dir, f, 999), many = peak_at_first_frame(dir, f, 999999);
  ASSERT_GT(few, 0);
  ASSERT_GT(many, 0);
  EXPECT_LT(many - few, 24 * 1024) << few << " KiB for 1,000 frames, " << many << " KiB for a million";
}

TEST(MeshGuards, EveryFileWrittenIsPrintedOnStdout) {
  TempDir dir;
  const fs::path f = scene(dir, "ball", kSphere);
  const RunResult obj = run_marchstudio(mesh(f, {"--resolution", "16", "-o", "part.obj"}), dir.path());
  ASSERT_EQ(obj.exit_code, 0) << obj.err;
  EXPECT_EQ(obj.out, "part.obj\npart.mtl\n");
  const RunResult ply = run_marchstudio(mesh(f, {"--resolution", "16", "-o", "out/part.ply"}), dir.path());
  ASSERT_EQ(ply.exit_code, 0) << ply.err;
  EXPECT_EQ(ply.out, "out/part.ply\n");
  const RunResult seq = run_marchstudio(mesh(f, {"--resolution", "16", "--frames", "0..1", "-o", "f_%02d.obj"}),
                                        dir.path());
  ASSERT_EQ(seq.exit_code, 0) << seq.err;
  EXPECT_EQ(seq.out, "f_00.obj\nf_00.mtl\nf_01.obj\nf_01.mtl\n");
  // A rerun writes nothing: both frames are complete.
  const RunResult again = run_marchstudio(mesh(f, {"--resolution", "16", "--frames", "0..1", "-o", "f_%02d.obj"}),
                                          dir.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, "");
}

}  // namespace
}  // namespace ms::test
