// [[animation]] of graph nodes in the scene layer (scene/graph_animation.h):
// targets resolve to the graph file's numbers, animated() rebuilds the
// graph with them (its box and the scene's bounds moving), and bad targets
// are one error naming the scene file, the line and the key.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "files.h"
#include "scene/animation.h"
#include "scene/graph_animation.h"
#include "scene/load.h"

namespace ms::test {
namespace {

const char* kGraph =
    "{\"root\": {\"op\": \"opUnion\", \"children\": [\n"
    "  {\"sdf\": \"sdSphere\", \"r\": 0.5, \"name\": \"ball\", \"translate\": [0, 1, 0], \"rotate\": [0, 0, 1, 10]},\n"
    "  {\"sdf\": \"sdBox\", \"b\": [0.2, 0.2, 0.2], \"name\": \"box\", \"scale\": 1}\n"
    "]}}\n";

Scene load_with(const TempDir& dir, const std::string& tracks) {
  write_file(dir / "g.json", kGraph);
  write_file(dir / "g.toml", "[scene]\ngraph = \"g.json\"\n\n[[materials]]\nname = \"m\"\ncolor = [1.0, 1.0, 1.0]\n\n" +
                                 tracks);
  return load_scene(dir / "g.toml");
}

std::string load_error(const TempDir& dir, const std::string& tracks) {
  try {
    load_with(dir, tracks);
  } catch (const Error& e) {
    return format_error(e.info());
  }
  return "no error";
}

TEST(GraphAnimationScene, TranslateMovesTheLeafAndTheBounds) {
  const TempDir dir;
  const Scene s = load_with(dir, "[[animation]]\ntarget = \"graph.ball.translate\"\n"
                                 "keys = [[0.0, 0.0, 1.0, 0.0], [2.0, 4.0, 1.0, 0.0]]\n");
  ASSERT_EQ(s.animation.size(), 1u);
  EXPECT_EQ(s.animation[0].arity, 3);
  EXPECT_TRUE(animates_graph(s));
  const Scene at0 = animated(s, 0.0), at1 = animated(s, 1.0);
  // x = 0 at t = 0, 2 at t = 1: the ball's box (rotated, so wider than
  // its radius) moves by 2, and the bounds, the box grown, with it.
  const float x0 = at0.graph->root_node().box.max.x, x1 = at1.graph->root_node().box.max.x;
  EXPECT_GT(x0, 0.5f);
  EXPECT_NEAR(x1 - x0, 2.0f, 1e-4f);
  EXPECT_GT(at1.bounds.max.x, x1);
  EXPECT_LT(at1.bounds.max.x, x1 + 0.01f);
  EXPECT_EQ(s.graph->root_node().box.max.x, at0.graph->root_node().box.max.x);  // the file's pose at t = 0
}

TEST(GraphAnimationScene, RotateAnglesScalesAndParametersAreOneValue) {
  const TempDir dir;
  const Scene s = load_with(dir, "[[animation]]\ntarget = \"graph.ball.rotate\"\nkeys = [[0.0, 10.0], [1.0, 90.0]]\n"
                                 "[[animation]]\ntarget = \"graph.box.scale\"\nkeys = [[0.0, 1.0], [1.0, 3.0]]\n"
                                 "[[animation]]\ntarget = \"graph.ball.r\"\nkeys = [[0.0, 0.5], [1.0, 1.5]]\n"
                                 "[[animation]]\ntarget = \"graph.box.b\"\nkeys = [[0.0, 0.2, 0.2, 0.2]]\n");
  ASSERT_EQ(s.animation.size(), 4u);
  EXPECT_EQ(s.animation[0].arity, 1);
  EXPECT_EQ(s.animation[1].arity, 1);
  EXPECT_EQ(s.animation[2].arity, 1);
  EXPECT_EQ(s.animation[3].arity, 3);
  const Scene at1 = animated(s, 1.0);
  // The box scaled 3x: 0.6 half-width; the ball 1.5 around (0, 1, 0).
  EXPECT_NEAR(at1.graph->root_node().box.max.x, 1.5f, 1e-3f);
  EXPECT_NEAR(at1.graph->root_node().box.max.y, 2.5f, 1e-3f);
  EXPECT_NEAR(at1.graph->root_node().box.min.y, -0.6f, 1e-3f);
}

TEST(GraphAnimationScene, BadTargetsNameTheFileLineAndKey) {
  const TempDir dir;
  std::string e = load_error(dir, "[[animation]]\ntarget = \"graph.bal.r\"\nkeys = [[0.0, 1.0]]\n");
  EXPECT_NE(e.find("g.toml:9"), std::string::npos) << e;
  EXPECT_NE(e.find("animation[0].target"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'ball'"), std::string::npos) << e;
  e = load_error(dir, "[[animation]]\ntarget = \"graph.box.translate\"\nkeys = [[0.0, 1.0, 1.0, 1.0]]\n");
  EXPECT_NE(e.find("has no 'translate' to animate"), std::string::npos) << e;
  e = load_error(dir, "[[animation]]\ntarget = \"graph.ball.translate\"\nkeys = [[0.0, 1.0]]\n");
  EXPECT_NE(e.find("must be 4 numbers"), std::string::npos) << e;  // the track's arity is translate's
  e = load_error(dir, "[[animation]]\ntarget = \"graph.ball.r\"\nkeys = [[0.0, -1.0]]\n");
  EXPECT_EQ(e, "no error");  // a value is checked where the graph is built: at the frame's time
  const Scene s = load_with(dir, "[[animation]]\ntarget = \"graph.ball.r\"\nkeys = [[0.0, -1.0]]\n");
  EXPECT_THROW(animated(s, 0.0), Error);
}

}  // namespace
}  // namespace ms::test
