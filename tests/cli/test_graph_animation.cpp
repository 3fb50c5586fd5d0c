// [[animation]] of a scene graph's nodes (docs/scene-graph.md#animation)
// through the real binary: a node's translate keyframed moves it in a
// sequence, each frame equal to a static scene with the node at that
// frame's value; frames after the first compile nothing (the values are
// buffers); mesh --frames follows the node; bad targets are one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "image_diff.h"
#include "io/image_io.h"
#include "mesh_read.h"
#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

// A ball named "ball" beside a box, the ball at `ball` (x, 0.5, 0).
std::string graph_json(const std::string& ball_x) {
  return "{\"root\": {\"op\": \"opUnion\", \"children\": [\n"
         "  {\"sdf\": \"sdSphere\", \"r\": 0.4, \"name\": \"ball\", \"translate\": [" + ball_x + ", 0.5, 0]},\n"
         "  {\"sdf\": \"sdBox\", \"b\": [0.3, 0.3, 0.3], \"name\": \"block\", \"translate\": [0, 0.3, 1.2]}\n"
         "]}}\n";
}

const char* kSceneHead =
    "[scene]\nname = \"anim\"\ngraph = \"anim.json\"\n\n"
    "[camera]\nposition = [0.0, 2.5, -5.0]\ntarget = [0.0, 0.4, 0.3]\nfov = 45.0\n\n"
    "[render]\nwidth = 96\nheight = 54\n\n"
    "[[lights]]\ntype = \"directional\"\ndirection = [0.4, -0.8, 0.3]\nintensity = 1.2\n\n"
    "[[materials]]\nname = \"part\"\ncolor = [0.7, 0.6, 0.5]\n";

// anim.toml moves the ball from x = -1 at t = 0 to x = 1 at t = 2;
// static.toml holds it at `x`.
void write_scenes(const TempDir& dir, const std::string& x) {
  write_file(dir / "anim.json", graph_json("-1"));
  write_file(dir / "anim.toml", std::string(kSceneHead) +
                                    "\n[[animation]]\ntarget = \"graph.ball.translate\"\n"
                                    "keys = [[0.0, -1.0, 0.5, 0.0], [2.0, 1.0, 0.5, 0.0]]\n");
  write_file(dir / "static.json", graph_json(x));
  std::string s = kSceneHead;
  s.replace(s.find("anim.json"), 9, "static.json");
  write_file(dir / "static.toml", s);
}

TEST(GraphAnimation, AnimatedTranslateMovesTheNodeAsAStaticSceneWouldPlaceIt) {
  const TempDir dir;
  write_scenes(dir, "0");  // frame 1 at 1 fps: t = 1, x = 0
  const RunResult seq = run_marchstudio({"render", "anim.toml", "--frames", "0..1", "--fps", "1", "-v", "-o",
                                         "f_%d.png"}, dir.path());
  ASSERT_EQ(seq.exit_code, 0) << seq.err;
  const RunResult still = run_marchstudio({"render", "static.toml", "--graph-eval", "interpreter", "-o", "s.png"},
                                          dir.path());
  ASSERT_EQ(still.exit_code, 0) << still.err;
  const Image f0 = read_image(dir / "f_0.png"), f1 = read_image(dir / "f_1.png"), s = read_image(dir / "s.png");
  EXPECT_GT(max_diff(f0, f1), 0.25);  // the ball moved across the frame
  // The static scene folds its bounds in, the animated one reads them as
  // uniforms: the same values, so the same pixels within one 8-bit step.
  EXPECT_LE(max_diff(f1, s), 1.0 / 255 + 1e-6);
  // A still at t = 1 is frame 1, as for any animation.
  const RunResult at1 = run_marchstudio({"render", "anim.toml", "--time", "1", "--fps", "1", "-o", "t1.png"},
                                        dir.path());
  ASSERT_EQ(at1.exit_code, 0) << at1.err;
  EXPECT_EQ(max_diff(read_image(dir / "t1.png"), f1), 0.0);
}

TEST(GraphAnimation, FramesAfterTheFirstCompileNoProgram) {
  const TempDir dir;
  write_scenes(dir, "0");
  const RunResult r = run_marchstudio({"render", "anim.toml", "--frames", "0..3", "--fps", "2", "-v", "-o",
                                       "f_%d.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (int f = 0; f <= 3; ++f)
    EXPECT_NE(r.err.find("frame " + std::to_string(f) + ": graph posed, 0 programs compiled, pruning "),
              std::string::npos)
        << r.err;
}

TEST(GraphAnimation, MeshFramesFollowTheNode) {
  const TempDir dir;
  write_scenes(dir, "0");
  const RunResult r = run_marchstudio({"mesh", "anim.toml", "--frames", "0..2", "--fps", "1", "--resolution", "32",
                                       "-o", "m_%d.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  float min_x[3];
  for (int f = 0; f < 3; ++f) {
    const std::vector<glm::vec3> v = read_obj(dir / ("m_" + std::to_string(f) + ".obj")).positions;
    ASSERT_FALSE(v.empty());
    min_x[f] = std::min_element(v.begin(), v.end(), [](auto a, auto b) { return a.x < b.x; })->x;
  }
  // The ball (radius 0.4) leads on -x: at x = -1, 0, 1 its left edge is
  // -1.4, then the box's -0.3 bounds the mesh from t = 1 on.
  EXPECT_NEAR(min_x[0], -1.4f, 0.1f);
  EXPECT_NEAR(min_x[1], -0.4f, 0.1f);
  EXPECT_NEAR(min_x[2], -0.3f, 0.1f);
}

TEST(GraphAnimation, AnUnknownNodeOrKeyIsOneLineWithADidYouMean) {
  const TempDir dir;
  write_scenes(dir, "0");
  const std::string scene = read_file(dir / "anim.toml");
  std::string bad = scene;
  bad.replace(bad.find("graph.ball.translate"), 20, "graph.bal.translate");
  write_file(dir / "bad_name.toml", bad);
  RunResult r = run_marchstudio({"render", "bad_name.toml", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err;
  EXPECT_NE(r.err.find("bad_name.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("animation[0].target"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no graph node is named 'bal'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'ball'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));

  bad = scene;
  bad.replace(bad.find("graph.ball.translate"), 20, "graph.ball.rr");
  write_file(dir / "bad_key.toml", bad);
  r = run_marchstudio({"render", "bad_key.toml", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err;
  EXPECT_NE(r.err.find("has no 'rr' to animate"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'r'"), std::string::npos) << r.err;
}

TEST(GraphAnimation, InlineEvaluationIsRefused) {
  const TempDir dir;
  write_scenes(dir, "0");
  const RunResult r = run_marchstudio({"render", "anim.toml", "--graph-eval", "inline", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--graph-eval inline cannot animate graph nodes"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
