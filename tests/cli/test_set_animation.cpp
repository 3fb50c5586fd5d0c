// `--set` of an animated key through the binary: the set value wins at
// every time (the image is the edited file's), the other tracks still
// play, and -v names the track that was dropped.
#include <gtest/gtest.h>

#include "image_diff.h"
#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

constexpr const char* kFovTrack = "\n[[animation]]\ntarget = \"camera.fov\"\nkeys = [ [0.0, 45.0], [2.0, 90.0] ]\n";

// tests/data/anim/orbit.toml (camera, ball and light animated), with a
// camera.fov track too, or with camera.fov = 30 and no such track.
struct Orbit {
  TempDir dir;
  std::string orbit = read_file(source_dir() / "tests/data/anim/orbit.toml");
  Orbit() {
    write_file(dir / "orbit.glsl", read_file(source_dir() / "tests/data/anim/orbit.glsl"));
    write_file(dir / "animated.toml", orbit + kFovTrack);
    std::string edited = orbit;
    const std::string fov = "fov      = 45.0";
    edited.replace(edited.find(fov), fov.size(), "fov      = 30.0");
    write_file(dir / "edited.toml", edited);
  }
  RunResult render(const std::string& scene, const std::string& out, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"render", (dir / scene).string(), "--size", "64x36", "--time", "1.5",
                                     "-o", (dir / out).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_marchstudio(args);
  }
  Image image(const std::string& out) { return read_image(dir / out); }
};

TEST(SetAnimation, SetBeatsTheTrackOfItsKey) {
  Orbit o;
  const RunResult set = o.render("animated.toml", "set.png", {"--set", "camera.fov=30", "-v"});
  ASSERT_EQ(set.exit_code, 0) << set.err;
  ASSERT_EQ(o.render("edited.toml", "edited.png").exit_code, 0);
  ASSERT_EQ(o.render("animated.toml", "track.png").exit_code, 0);
  EXPECT_EQ(max_diff(o.image("set.png"), o.image("edited.png")), 0.0) << "--set camera.fov=30 is not fov 30";
  EXPECT_GT(max_diff(o.image("track.png"), o.image("edited.png")), 0.05) << "the fov track did nothing here";
  EXPECT_NE(set.err.find("note: --set camera.fov replaces the [[animation]] of 'camera.fov' at line "),
            std::string::npos)
      << set.err;
  // The note is for -v only.
  const RunResult quiet = o.render("animated.toml", "quiet.png", {"--set", "camera.fov=30"});
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("replaces"), std::string::npos) << quiet.err;
}

TEST(SetAnimation, MeshSaysItUnderVerboseToo) {
  Orbit o;
  const RunResult r =
      run_marchstudio({"mesh", (o.dir / "animated.toml").string(), "--resolution", "16", "--bounds", "-2,-2,-2,2,2,2",
                       "--set", "camera.fov=30", "-v", "-o", (o.dir / "ball.obj").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("note: --set camera.fov replaces the [[animation]] of 'camera.fov' at line "),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace ms::test
