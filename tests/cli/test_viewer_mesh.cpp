// The viewer exports the scene as it stands (docs/viewer.md#exporting-a-mesh):
// --mesh-on-exit writes the mesh once the window closes, with the panel's
// values and the time at that moment; M (scripted here by --mesh-frame)
// writes <scene>_mesh_NNN.obj in the current directory while the window
// keeps drawing; a failed export is one line, never the viewer's end but
// for --mesh-on-exit's exit 3. Under Xvfb, the real binary and its child.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A ball whose radius is the panel's slider uRadius, inside [bounds].
const char* const kRadiusScene = R"([scene]
map = "ball.glsl"
[camera]
position = [0.0, 1.0, -5.0]
target = [0.0, 1.0, 0.0]
[render]
width = 160
height = 90
[bounds]
center = [0.0, 1.0, 0.0]
radius = 1.3
[[materials]]
name = "ball"
color = [0.85, 0.10, 0.06]
)";
const char* const kRadiusMap = R"(uniform float uRadius = 0.6;  // range(0.2, 1.2)
vec2 map(vec3 p) { return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), uRadius), MAT_BALL); }
)";

std::vector<glm::vec3> obj_vertices(const fs::path& file) {
  std::vector<glm::vec3> v;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    glm::vec3 p;
    s >> p.x >> p.y >> p.z;
    v.push_back(p);
  }
  return v;
}

// The vertices' distances from the ball's centre: smallest and largest.
std::pair<double, double> radius_range(const std::vector<glm::vec3>& v) {
  double lo = 1e9, hi = 0.0;
  for (const glm::vec3& p : v) {
    const double r = glm::length(p - glm::vec3(0.0f, 1.0f, 0.0f));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return {lo, hi};
}

std::vector<std::string> nonempty_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

class ViewerMesh : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
    write_file(dir / "ball.toml", kRadiusScene);
    write_file(dir / "ball.glsl", kRadiusMap);
    fs::create_directories(dir / "cwd");
  }
  // The viewer on `scene` until it quits by itself; its exit code.
  int view(const fs::path& scene, std::vector<std::string> extra) {
    std::vector<std::string> argv = {"env", x_display(), MARCH_BIN, "view",
                                     scene.string(), "--size", "160x90", "--paused", "--no-panel",
                                     "--log", log().string(), "--mesh-resolution", "32"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    BackgroundProcess proc(argv, dir / "out.txt", dir / "err.txt", dir / "cwd");
    EXPECT_TRUE(proc.started());
    const int code = proc.wait_exit(240);
    EXPECT_NE(code, -1) << "the viewer did not quit\n" << read_file(log());
    return code;
  }
  std::string err() const { return read_file(dir / "err.txt"); }
  fs::path log() const { return dir / "log.txt"; }
  TempDir dir;
};

TEST_F(ViewerMesh, OnExitWritesTheSeed) {
  const fs::path out = dir / "seed.obj";
  ASSERT_EQ(view(source_dir() / "scenes/seed.toml", {"--max-frames", "3", "--mesh-on-exit", out.string()}), 0)
      << err();
  const std::vector<glm::vec3> v = obj_vertices(out);
  ASSERT_GT(v.size(), 100u) << err();
  // The seed's unit ball; a cell of its 32^3 grid is 2.04 / 32 = 0.064.
  const auto [lo, hi] = radius_range(v);
  EXPECT_NEAR(lo, 1.0, 0.064);
  EXPECT_NEAR(hi, 1.0, 0.064);
  EXPECT_NE(err().find("wrote " + out.string() + " ("), std::string::npos) << err();
  EXPECT_FALSE(wait_for_line(log(), "^mesh wrote .*watertight", 0).empty()) << read_file(log());
}

// A scripted drag of the panel's slider moves the exported surface with
// it; --uniform's start value does too, and without either the file's 0.6.
TEST_F(ViewerMesh, ThePanelsValuesAreExported) {
  struct Case {
    std::vector<std::string> flags;
    double radius;
  };
  const std::vector<Case> cases = {
      {{}, 0.6}, {{"--uniform", "uRadius=0.8"}, 0.8}, {{"--drag", "uRadius=1.0@2..4"}, 1.0}};
  for (const Case& c : cases) {
    const fs::path out = dir / "ball.obj";
    fs::remove(out);
    std::vector<std::string> flags = {"--max-frames", "12", "--mesh-on-exit", out.string()};
    flags.insert(flags.end(), c.flags.begin(), c.flags.end());
    ASSERT_EQ(view(dir / "ball.toml", flags), 0) << err();
    const std::vector<glm::vec3> v = obj_vertices(out);
    ASSERT_GT(v.size(), 100u) << err();
    const auto [lo, hi] = radius_range(v);  // a cell is 2.6 / 32 = 0.081
    EXPECT_NEAR(lo, c.radius, 0.081) << c.radius;
    EXPECT_NEAR(hi, c.radius, 0.081) << c.radius;
  }
}

TEST_F(ViewerMesh, AnUnwritableExitFileIsExit3AndOneLine) {
  write_file(dir / "file", "a file, not a directory");
  const fs::path out = dir / "file" / "x.obj";
  EXPECT_EQ(view(dir / "ball.toml", {"--max-frames", "2", "--mesh-on-exit", out.string()}), 3);
  const std::vector<std::string> lines = nonempty_lines(err());
  ASSERT_EQ(lines.size(), 1u) << err();
  EXPECT_EQ(lines[0].rfind("marchstudio: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find((dir / "file").string()), std::string::npos) << lines[0];
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ViewerMesh, ABadExitFileIsABadFlag) {
  const RunResult r = run_marchstudio({"view", (dir / "ball.toml").string(), "--mesh-on-exit", "x.txt"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--mesh-on-exit"), std::string::npos) << r.err;
  const RunResult d = run_marchstudio({"view", (dir / "ball.toml").string(), "--drag", "uRadiu=1@1..2"});
  EXPECT_EQ(d.exit_code, 2) << d.err;
  EXPECT_NE(d.err.find("uRadiu"), std::string::npos) << d.err;
  const RunResult far = run_marchstudio({"view", (dir / "ball.toml").string(), "--drag", "uRadius=5@1..2"});
  EXPECT_EQ(far.exit_code, 2) << far.err;
  EXPECT_NE(far.err.find("range"), std::string::npos) << far.err;
}

// The key's export (M; --mesh-frame presses it after a settled frame): the
// next free <stem>_mesh_NNN.obj in the current directory, written by the
// child while the window keeps drawing, reported in the log and overlay.
TEST_F(ViewerMesh, TheKeyWritesTheNextFreeFile) {
  write_file(dir / "cwd" / "ball_mesh_001.obj", "taken");
  ASSERT_EQ(view(dir / "ball.toml", {"--mesh-frame", "2", "--exit-after", "60", "--max-frames", "400"}), 0) << err();
  EXPECT_EQ(read_file(dir / "cwd" / "ball_mesh_001.obj"), "taken");
  const std::vector<glm::vec3> v = obj_vertices(dir / "cwd" / "ball_mesh_002.obj");
  ASSERT_GT(v.size(), 100u) << read_file(log()) << err();
  const std::string writing = wait_for_line(log(), "^mesh writing ball_mesh_002.obj$", 0);
  EXPECT_FALSE(writing.empty()) << read_file(log());
  EXPECT_FALSE(wait_for_line(log(), "^mesh wrote ball_mesh_002.obj \\([0-9]+ triangles, watertight\\)$", 0).empty())
      << read_file(log());
}

// A Shadertoy shader has no map(): the key's export fails in the child, the
// viewer says why and runs on; --mesh-on-exit's failure is exit 3.
TEST_F(ViewerMesh, AShadertoyShaderHasNoMesh) {
  write_file(dir / "toy.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / iResolution.x); }\n");
  EXPECT_EQ(view(dir / "toy.glsl", {"--mesh-frame", "2", "--max-frames", "200", "--exit-after", "60"}), 0) << err();
  const std::string failed = wait_for_line(log(), "^mesh failed -- ", 0);
  EXPECT_FALSE(failed.empty()) << read_file(log());
  EXPECT_NE(failed.find("map()"), std::string::npos) << failed;
  EXPECT_FALSE(wait_for_line(log(), "^exit frames=", 0).empty());
  EXPECT_EQ(view(dir / "toy.glsl", {"--max-frames", "2", "--mesh-on-exit", (dir / "toy.obj").string()}), 3);
  EXPECT_EQ(nonempty_lines(err()).size(), 1u) << err();
}

}  // namespace
}  // namespace ms::test
