// The viewer compiles what `render` compiles: lights,
// materials and sky folded into constants; a scripted panel drag (--drag)
// keeps the dragged value (only it) a uniform until the drag ends, then
// folds the final value; the builds compile on the worker. Under Xvfb; images against `render` within 1/255,
// what is a uniform read from the assembled text (the `values` log line).
#include <gtest/gtest.h>

#include <algorithm>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// kBallScene with a specular ball, so the folded material table matters.
const std::string kScene = std::string(kBallScene) + "specular = 0.6\n";

class FoldedViewer : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
    write_file(dir / "seed.toml", kScene);
    write_file(dir / "seed.glsl", kBallMap);
  }
  void start(std::vector<std::string> extra) {
    std::vector<std::string> argv = {"env", x_display(), MARCH_BIN, "view",
                                     (dir / "seed.toml").string(), "--size", "160x90", "--paused", "--no-panel",
                                     "--log", log().string(), "--capture-dir", (dir / "cap").string(),
                                     "--shot-dir", (dir / "shots").string(), "--exit-after", "90"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    proc = std::make_unique<BackgroundProcess>(argv, dir / "out.txt", dir / "err.txt");
    ASSERT_TRUE(proc->started());
    ASSERT_FALSE(wait_for_line(log(), "^reload ok 0 ", 60).empty()) << read_file(log()) << read_file(dir / "err.txt");
    ASSERT_FALSE(wait_for_line(log(), "^capture 0 ", 10).empty());
  }
  Image render(std::vector<std::string> more) {
    std::vector<std::string> args = {"render", (dir / "seed.toml").string(), "--size", "160x90", "-o",
                                     (dir / "render.png").string()};
    args.insert(args.end(), more.begin(), more.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_image(dir / "render.png");
  }
  std::vector<std::string> values_lines() {
    std::vector<std::string> out;
    for (const std::string& l : file_lines(log()))
      if (l.rfind("values ", 0) == 0) out.push_back(l);
    return out;
  }
  fs::path log() const { return dir / "log.txt"; }

  TempDir dir;
  std::unique_ptr<BackgroundProcess> proc;
};

// The ball's colour dragged over frames 3..8: live (its own uniform)
// from the first frame after the drag starts, folded again after it ends;
// the shot after the drag is render of the edited scene, the first frame
// render of the file.
TEST_F(FoldedViewer, ADragIsLiveThenFoldedAtItsFinalValue) {
  start({"--drag", "materials[1].color=0.1,0.3,0.9@3..8", "--shot-frame", "20"});
  ASSERT_FALSE(wait_for_line(log(), "^screenshot ", 60).empty()) << read_file(log()) << read_file(dir / "err.txt");
  const std::vector<std::string> v = values_lines();
  ASSERT_EQ(v.size(), 2u) << read_file(log());
  // Only the dragged value is a uniform: the material table stays folded.
  EXPECT_EQ(v[0].rfind("values ok live=materials[1].color uniforms=materials[1].color fused=1 frame=", 0), 0u)
      << v[0];
  // Live right after the drag's first step, folded again as many frames
  // later as the drag lasts (frame = frames drawn before the rebuild).
  EXPECT_GE(field(v[0], "frame"), 4) << v[0];
  EXPECT_LE(field(v[0], "frame"), 5) << v[0];
  EXPECT_EQ(v[1].rfind("values ok live=none uniforms=none fused=1 frame=", 0), 0u) << v[1];
  EXPECT_EQ(field(v[1], "frame") - field(v[0], "frame"), 5) << v[1];

  // spp 1, no accumulation: render's one-pass frame, as `render` draws it.
  EXPECT_FALSE(wait_for_line(log(), "^program fused=1 dispatch=fragment$", 1).empty()) << read_file(log());
  EXPECT_NE(v[0].find(" fused=1 "), std::string::npos) << "the live program is one pass too: " << v[0];
  const Image file = render({}), edited = render({"--set", "materials.ball.color=[0.1,0.3,0.9]"});
  EXPECT_LE(max_abs_diff(read_image(dir / "cap/frame_0.png"), file), 1.0 / 255.0)
      << "the viewer's folded first frame is not render's";
  const Image shot = read_image(dir / "shots/seed_1.png");
  EXPECT_LE(max_abs_diff(shot, edited), 1.0 / 255.0) << "after the drag the frame is not render of the edited scene";
  EXPECT_GT(mean_abs_diff(shot, file), 1e-3) << "the drag changed nothing";
}

// Mid-drag the live program draws the value as it stands: the shot after
// frame 6 (re-rendered, as P does) has the colour the drag set before that
// frame's draw, 2/5 of the way (frame 5 of 3..8), and equals render of it.
TEST_F(FoldedViewer, MidDragTheLiveProgramShowsTheCurrentValue) {
  start({"--drag", "materials[1].color=0.1,0.3,0.9@3..8", "--shot-frame", "6"});
  ASSERT_FALSE(wait_for_line(log(), "^screenshot ", 60).empty()) << read_file(log()) << read_file(dir / "err.txt");
  const std::vector<std::string> v = values_lines();
  ASSERT_GE(v.size(), 1u) << read_file(log());
  EXPECT_EQ(v[0].rfind("values ok live=materials[1].color uniforms=materials[1].color ", 0), 0u) << v[0];
  const Image shot = read_image(dir / "shots/seed_1.png");
  // 0.85 + (0.1 - 0.85) * 0.4, 0.1 + (0.3 - 0.1) * 0.4, 0.06 + (0.9 - 0.06) * 0.4
  const Image mid = render({"--set", "materials.ball.color=[0.55,0.18,0.396]"});
  EXPECT_LE(max_abs_diff(shot, mid), 1.0 / 255.0) << "mid-drag the frame is not render of the dragged value";
  EXPECT_GT(mean_abs_diff(shot, render({})), 1e-3) << "mid-drag the frame still shows the file's value";
}

// Each kind of folded value, dragged: only that value is live (its own
// uniform, the log's uniforms= names it), and the shot mid-drag (frame 6
// of the drag over 3..8: 2/5 of the way) is render of the value there.
struct DragCase {
  const char* name;   // the test's name
  const char* drag;   // --drag TARGET=V@3..8
  const char* live;   // the values line's live= and uniforms=
  const char* set;    // render --set of the value 2/5 of the way
};
void PrintTo(const DragCase& c, std::ostream* os) { *os << c.drag; }
class FoldedDrag : public FoldedViewer, public ::testing::WithParamInterface<DragCase> {};

TEST_P(FoldedDrag, OnlyTheDraggedValueIsLiveAndShowsAsRender) {
  const DragCase& c = GetParam();
  write_file(dir / "seed.toml", kScene + "[sky]\nzenith = [0.2, 0.4, 0.8]\n");
  start({"--drag", std::string(c.drag) + "@3..8", "--shot-frame", "6"});
  ASSERT_FALSE(wait_for_line(log(), "^screenshot ", 60).empty()) << read_file(log()) << read_file(dir / "err.txt");
  const std::vector<std::string> v = values_lines();
  ASSERT_GE(v.size(), 1u) << read_file(log());
  const std::string live = c.live;
  EXPECT_EQ(v[0].rfind("values ok live=" + live + " uniforms=" + live + " ", 0), 0u) << v[0];
  const Image shot = read_image(dir / "shots/seed_1.png");
  EXPECT_LE(max_abs_diff(shot, render({"--set", c.set})), 1.0 / 255.0) << "mid-drag the frame is not render of " << c.set;
  EXPECT_GT(mean_abs_diff(shot, render({})), 1e-4) << "the drag changed nothing";
}

INSTANTIATE_TEST_SUITE_P(
    Values, FoldedDrag,
    ::testing::Values(
        DragCase{"LightPosition", "lights[0].position=-4,5,-1.5", "lights[0].position", "lights[0].position=[0.8,5,-1.5]"},
        DragCase{"LightIntensity", "lights[0].intensity=4", "lights[0].color", "lights[0].intensity=2.8"},
        DragCase{"MaterialSpecular", "materials[1].specular=0", "materials[1].specular", "materials.ball.specular=0.36"},
        DragCase{"SkyZenith", "sky.zenith=0.7,0.4,0.3", "sky.zenith", "sky.zenith=[0.4,0.4,0.6]"}),
    [](const ::testing::TestParamInfo<DragCase>& i) { return std::string(i.param.name); });

// Accumulating (or in a debug view) the frame is the accumulating pass and
// post; turning accumulation off (--accumulate 1) gives the one-pass frame.
TEST_F(FoldedViewer, AccumulatingIsNotTheOnePassFrame) {
  start({"--accumulate", "4", "--max-frames", "8"});
  EXPECT_FALSE(wait_for_line(log(), "^program fused=0 dispatch=fragment$", 5).empty()) << read_file(log());
  ASSERT_FALSE(wait_for_line(log(), "^exit ", 30).empty());
  EXPECT_EQ(read_file(log()).find("fused=1"), std::string::npos) << read_file(log());
}

TEST_F(FoldedViewer, ADebugViewIsNotTheOnePassFrame) {
  start({"--debug-view", "2", "--max-frames", "4"});
  EXPECT_FALSE(wait_for_line(log(), "^program fused=0 dispatch=fragment$", 5).empty()) << read_file(log());
}

TEST_F(FoldedViewer, TheOnePassFrameIsRendersAtSpp1) {
  start({"--accumulate", "1"});
  EXPECT_FALSE(wait_for_line(log(), "^program fused=1 dispatch=fragment$", 5).empty()) << read_file(log());
  EXPECT_LE(max_abs_diff(read_image(dir / "cap/frame_0.png"), render({})), 1.0 / 255.0);
}

TEST_F(FoldedViewer, ABadDragIsOneLineAndExit2) {
  for (const std::string& bad : {"materials[1].colour=1,0,0@1..2", "materials[1].color=1@1..2",
                                 "materials[1].color=1,0,0@5..2", "materials[9].color=1,0,0@1..2", "nonsense"}) {
    const RunResult r = run_marchstudio({"view", (dir / "seed.toml").string(), "--drag", bad});
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
    EXPECT_NE(r.err.find("--drag"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace ms::test
