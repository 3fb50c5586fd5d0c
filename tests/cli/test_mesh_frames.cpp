// `mesh --frames A..B -o PATTERN` through the real binary: one mesh per
// frame at time frame / fps, and resume as a render sequence resumes: a
// rerun keeps each complete frame with this run's stamp (io/file_stamp.h)
// and meshes again the missing, cut-short and stale ones.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "mesh_read.h"
#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

// A sphere whose radius grows with time: r = base + 0.2 t.
void write_scene(const TempDir& dir, const std::string& base) {
  write_file(dir / "grow.glsl", "vec2 map(vec3 p) {\n  return vec2(length(p) - (" + base +
                                    " + 0.2 * uTime), MAT_PART);\n}\n");
  write_file(dir / "grow.toml",
             "[scene]\nname = \"grow\"\nmap = \"grow.glsl\"\n\n[bounds]\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, "
             "1.0]\n\n[[materials]]\nname = \"part\"\ncolor = [0.7, 0.7, 0.75]\n");
}

RunResult mesh_frames(const TempDir& dir, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"mesh", "grow.toml", "--frames", "0..2", "--fps", "1", "--resolution", "16",
                                   "-o", "f_%02d.obj"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_marchstudio(args, dir.path());
}

std::map<int, fs::file_time_type> mtimes(const TempDir& dir) {
  std::map<int, fs::file_time_type> t;
  for (int f = 0; f < 3; ++f) t[f] = fs::last_write_time(dir / ("f_0" + std::to_string(f) + ".obj"));
  return t;
}

TEST(MeshFrames, OneMeshPerFrameAtItsTime) {
  TempDir dir;
  write_scene(dir, "0.4");
  const RunResult r = mesh_frames(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, " meshed in "), 3) << r.err;
  EXPECT_EQ(count_of(r.out, ".obj\n"), 3) << r.out;
  std::vector<std::size_t> counts;
  for (int f = 0; f < 3; ++f) {
    const std::vector<glm::vec3> v = read_obj(dir / ("f_0" + std::to_string(f) + ".obj")).positions;
    ASSERT_FALSE(v.empty()) << "frame " << f;
    counts.push_back(v.size());
    // Frame f is at time f (--fps 1): its radius is 0.4 + 0.2 f, within a voxel (2 / 16).
    double mean = 0.0;
    for (const glm::vec3& x : v) mean += glm::length(x);
    EXPECT_NEAR(mean / v.size(), 0.4 + 0.2 * f, 0.125 / 2) << "frame " << f;
    EXPECT_TRUE(fs::exists(dir / ("f_0" + std::to_string(f) + ".mtl")));
  }
  EXPECT_LT(counts[0], counts[1]);
  EXPECT_LT(counts[1], counts[2]);
}

TEST(MeshFrames, ARerunResumesAndRedoesOnlyWhatIsNotComplete) {
  TempDir dir;
  write_scene(dir, "0.4");
  ASSERT_EQ(mesh_frames(dir).exit_code, 0);
  const std::string frame1 = read_file(dir / "f_01.obj");
  auto before = mtimes(dir);

  RunResult r = mesh_frames(dir);  // everything complete
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, " skipped: "), 3) << r.err;
  EXPECT_EQ(count_of(r.err, " meshed in "), 0) << r.err;
  EXPECT_EQ(mtimes(dir), before);

  fs::remove(dir / "f_01.obj");  // missing: meshed again, the same
  r = mesh_frames(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, " skipped: "), 2) << r.err;
  EXPECT_EQ(count_of(r.err, "frame 1 meshed in "), 1) << r.err;
  EXPECT_EQ(read_file(dir / "f_01.obj"), frame1);
  EXPECT_EQ(fs::last_write_time(dir / "f_00.obj"), before[0]);

  before = mtimes(dir);
  fs::resize_file(dir / "f_02.obj", fs::file_size(dir / "f_02.obj") / 2);  // cut short
  r = mesh_frames(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "frame 2: "), 1) << r.err;
  EXPECT_EQ(count_of(r.err, "frame 2 meshed in "), 1) << r.err;
  EXPECT_EQ(count_of(r.err, " skipped: "), 2) << r.err;
  EXPECT_FALSE(read_obj(dir / "f_02.obj").positions.empty());
  EXPECT_EQ(fs::last_write_time(dir / "f_00.obj"), before[0]);
  EXPECT_EQ(fs::last_write_time(dir / "f_01.obj"), before[1]);

  fs::remove(dir / "f_00.mtl");  // a part of frame 0 gone
  r = mesh_frames(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "frame 0 meshed in "), 1) << r.err;
  EXPECT_TRUE(fs::exists(dir / "f_00.mtl"));
}

TEST(MeshFrames, AnotherSceneOrResolutionOrForceRedoesEveryFrame) {
  TempDir dir;
  write_scene(dir, "0.4");
  ASSERT_EQ(mesh_frames(dir).exit_code, 0);
  const std::string frame0 = read_file(dir / "f_00.obj");
  write_scene(dir, "0.45");
  RunResult r = mesh_frames(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, " meshed in "), 3) << r.err;
  EXPECT_EQ(count_of(r.err, "other inputs or settings"), 3) << r.err;
  EXPECT_NE(read_file(dir / "f_00.obj"), frame0);

  r = run_marchstudio({"mesh", "grow.toml", "--frames", "0..2", "--fps", "1", "--resolution", "20", "-o",
                       "f_%02d.obj"},
                      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, " meshed in "), 3) << r.err;

  r = run_marchstudio({"mesh", "grow.toml", "--frames", "0..2", "--fps", "1", "--resolution", "20", "-o",
                       "f_%02d.obj", "--force"},
                      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, " meshed in "), 3) << r.err;
  EXPECT_EQ(count_of(r.err, " skipped: "), 0) << r.err;
}

TEST(MeshFrames, BadPatternsAndFlagsAreOneLineAndNoFile) {
  TempDir dir;
  write_scene(dir, "0.4");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--frames", "0..2", "-o", "b.obj"}, "no frame field"},
      {{"--frames", "0..2", "-o", "b_%d_%d.obj"}, "more than one"},
      {{"--frames", "0..2", "-o", "b_%d.xyz"}, "mesh format"},
      {{"--frames", "0..2", "-o", "b_%d.obj", "--time", "1"}, "--time"},
      {{"--frames", "0..2", "-o", "b_%d.obj", "--fps", "0"}, "--fps"},
      {{"--frames", "2..1", "-o", "b_%d.obj"}, "--frames"},
      {{"--force", "-o", "b.obj"}, "--force"},
      {{"-o", "b_%d.obj"}, "--frames"},
  };
  for (const auto& [flags, needle] : cases) {
    std::vector<std::string> args = {"mesh", "grow.toml", "--resolution", "16"};
    args.insert(args.end(), flags.begin(), flags.end());
    const RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << flags[1] << ": " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_EQ(count_of(r.err, "\n"), 1) << "one line: " << r.err;
    EXPECT_EQ(dir.entries().size(), 2u) << "nothing but the scene after " << r.err;
  }
}

}  // namespace
}  // namespace ms::test
