// The graph's one-child modifiers and profiles (docs/scene-graph.md,
// "Modifiers"): what each accepts and refuses, the boxes and bounds it
// derives from its child's, and the GLSL both evaluators get.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <string>

#include "files.h"
#include "graph_of.h"
#include "scene/graph_unary.h"
#include "shader/graph_glsl.h"
#include "shader/graph_interp.h"

namespace ms::test {
namespace {

std::string sphere(float r) { return R"({"sdf": "sdSphere", "r": )" + std::to_string(r) + "}"; }
std::string wrap(const std::string& node) { return R"({"root": )" + node + "}"; }

TEST(GraphModifiers, ARepetitionsBoxHoldsEveryCopy) {
  const SceneGraph g = graph_of(wrap(R"({"op": "repeat", "spacing": [1, 0, 0.5], "count": [2, 0, 1], "children": [)" +
                                     sphere(0.3f) + "]}"));
  const GraphNode& r = g.root_node();
  EXPECT_TRUE(r.unary);
  EXPECT_NEAR(r.box.min.x, -2.3f, 1e-3f);
  EXPECT_NEAR(r.box.max.x, 2.3f, 1e-3f);
  EXPECT_NEAR(r.box.max.y, 0.3f, 1e-3f);
  EXPECT_NEAR(r.box.max.z, 0.8f, 1e-3f);
  EXPECT_FLOAT_EQ(r.lipschitz, 1.0f);
}

TEST(GraphModifiers, TwistsBoundGrowsWithItsRateAndTheChildsRadius) {
  const SceneGraph g = graph_of(wrap(R"({"op": "twist", "k": 2, "children": [{"sdf": "sdBox", "b": [0.3, 1, 0.4]}]})"));
  const float a = 2.0f * 0.5f;  // the box's corners lie 0.5 from the y axis
  EXPECT_NEAR(g.root_node().lipschitz, 0.5f * (a + std::sqrt(a * a + 4.0f)), 1e-4f);
  EXPECT_NEAR(g.root_node().box.max.x, 0.5f, 1e-3f);  // a cylinder of radius 0.5 about y
  EXPECT_NEAR(g.root_node().box.max.y, 1.0f, 1e-3f);
}

TEST(GraphModifiers, AModifiersTransformMovesItsWholeFrame) {
  const SceneGraph g = graph_of(wrap(R"({"op": "round", "r": 0.1, "translate": [2, 0, 0], "scale": 2, "children": [)" +
                                     sphere(0.5f) + "]}"));
  // (0.5 + 0.1) * 2 about x = 2.
  EXPECT_NEAR(g.root_node().box.max.x, 3.2f, 1e-3f);
  EXPECT_NEAR(g.root_node().box.min.x, 0.8f, 1e-3f);
}

TEST(GraphModifiers, ProfilesBecomeSolidsThroughExtrudeAndRevolve) {
  const SceneGraph e = graph_of(wrap(R"({"op": "extrude", "h": 0.4, "children": [{"sdf": "sd2Box", "b": [1, 0.5], "rotate": 90}]})"));
  EXPECT_NEAR(e.root_node().box.max.x, 0.5f, 1e-3f);  // turned a quarter about z
  EXPECT_NEAR(e.root_node().box.max.z, 0.2f, 1e-3f);
  const SceneGraph r = graph_of(wrap(R"({"op": "revolve", "offset": 1, "children": [{"sdf": "sd2Circle", "r": 0.25}]})"));
  EXPECT_NEAR(r.root_node().box.max.x, 1.25f, 1e-3f);
  EXPECT_NEAR(r.root_node().box.max.y, 0.25f, 1e-3f);
}

TEST(GraphModifiers, MistakesAreOneLineAtTheirPointer) {
  EXPECT_NE(graph_error(wrap(R"({"sdf": "sd2Circle", "r": 1})")).find("must be inside an 'extrude' or 'revolve'"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "extrude", "h": 1, "children": [)" + sphere(1) + "]}")).find("/root/children/0/sdf"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "twist", "k": 1, "children": [)" + sphere(1) + "," + sphere(2) + "]}"))
                .find("takes one child"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "twisst", "k": 1, "children": [)" + sphere(1) + "]}")).find("did you mean 'twist'"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "onoin", "t": 1, "children": [)" + sphere(1) + "]}")).find("did you mean 'onion'"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "repeat", "spacing": [1, 0, 0], "count": [1.5, 0, 0], "children": [)" +
                             sphere(0.2f) + "]}"))
                .find("whole numbers"),
            std::string::npos);
  // A derived parameter is not a key a file may set.
  EXPECT_NE(graph_error(wrap(R"({"op": "twist", "k": 1, "l": 1, "children": [)" + sphere(1) + "]}")).find("unknown key 'l'"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "opBlend", "t": 1.5, "children": [)" + sphere(1) + "," + sphere(2) + "]}"))
                .find("must be in [0, 1]"),
            std::string::npos);
  // Infinite repetition is unbounded unless something cuts it.
  EXPECT_NE(graph_error(wrap(R"({"op": "repeat", "spacing": [1, 0, 0], "children": [)" + sphere(0.2f) + "]}"))
                .find("unbounded"),
            std::string::npos);
}

// A polygon from a vertex list: its box, both evaluators' GLSL, and the
// lists it refuses.
TEST(GraphModifiers, APolygonTakesItsVerticesAsAList) {
  const std::string poly = R"({"op": "extrude", "h": 0.2, "children": [{"sdf": "sd2Polygon", "v": [[-1, -0.5], [2, 0], [0, 1.5]]}]})";
  const SceneGraph g = graph_of(wrap(poly));
  EXPECT_NEAR(g.root_node().box.min.x, -1.0f, 1e-3f);
  EXPECT_NEAR(g.root_node().box.max.x, 2.0f, 1e-3f);
  EXPECT_NEAR(g.root_node().box.min.y, -0.5f, 1e-3f);
  EXPECT_NEAR(g.root_node().box.max.y, 1.5f, 1e-3f);
  // Count 3, then the array, its last vertex repeated to fill.
  const std::string inl = graph_map_inline(g);
  EXPECT_NE(inl.find("sd2Polygon("), std::string::npos);
  EXPECT_NE(inl.find(", 3.0, vec2[32](vec2((-1.0), (-0.5)), vec2(2.0, 0.0), vec2(0.0, 1.5), vec2(0.0, 1.5), "), std::string::npos)
      << inl;
  const std::string e1 = graph_error(wrap(R"({"op": "extrude", "h": 1, "children": [{"sdf": "sd2Polygon", "v": [[0, 0], [1, 0]]}]})"));
  EXPECT_NE(e1.find("'v' must be an array of 3 to 32 [x, y] points"), std::string::npos) << e1;
  EXPECT_NE(e1.find("/root/children/0/v"), std::string::npos) << e1;
  const std::string e2 = graph_error(wrap(R"({"op": "extrude", "h": 1, "children": [{"sdf": "sd2Polygon", "v": [[0, 0], [1, 0], [1, 0], [0, 1]]}]})"));
  EXPECT_NE(e2.find("/root/children/0/v/2: a point of 'v' repeats the one before it"), std::string::npos) << e2;
  const std::string e3 = graph_error(wrap(R"({"op": "extrude", "h": 1, "children": [{"sdf": "sd2Polygon", "v": [[0, 0], [1, 0], [0, 1], [0, 0]]}]})"));
  EXPECT_NE(e3.find("closes itself"), std::string::npos) << e3;
  const std::string e4 = graph_error(wrap(R"({"op": "extrude", "h": 1, "children": [{"sdf": "sd2Polygon", "v": [[0, 0], [1, 0, 2], [0, 1]]}]})"));
  EXPECT_NE(e4.find("each point of 'v' must be an array of 2 numbers"), std::string::npos) << e4;
  std::string many = R"({"op": "extrude", "h": 1, "children": [{"sdf": "sd2Polygon", "v": [)";
  for (int i = 0; i < 33; ++i) many += (i ? ", [" : "[") + std::to_string(std::cos(i * 0.19)) + ", " + std::to_string(std::sin(i * 0.19)) + "]";
  EXPECT_NE(graph_error(wrap(many + "]}]}")).find("it has 33"), std::string::npos);
}

// What would make a shader loop or nest without end is refused at the node.
TEST(GraphModifiers, HostileRepetitionsAndNestingAreRefused) {
  EXPECT_NE(graph_error(wrap(R"({"op": "repeat", "spacing": [0.001, 0.001, 0.001], "count": [1000, 1000, 1000], "children": [)" +
                             sphere(1) + "]}"))
                .find("copies (at most 1024)"),
            std::string::npos);
  EXPECT_NE(graph_error(wrap(R"({"op": "polar", "count": 1e9, "radius": 1, "children": [)" + sphere(0.1f) + "]}"))
                .find("at most 1024"),
            std::string::npos);
  std::string deep = sphere(0.5f);
  for (int i = 0; i < kMaxModifierDepth + 1; ++i) deep = R"({"op": "round", "r": 0.001, "children": [)" + deep + "]}";
  const std::string e = graph_error(wrap(deep));
  EXPECT_NE(e.find("modifiers nest 65 deep"), std::string::npos) << e;
  EXPECT_NE(e.find("/root"), std::string::npos) << e;
  EXPECT_NE(graph_error(wrap(R"({"op": "twist", "k": 1e20, "children": [)" + sphere(1) + "]}")).find("Lipschitz bound"),
            std::string::npos);
  // At the limit it builds, and a wide repetition of small copies is fine.
  deep = sphere(0.5f);
  for (int i = 0; i < kMaxModifierDepth; ++i) deep = R"({"op": "round", "r": 0.001, "children": [)" + deep + "]}";
  EXPECT_NO_THROW(graph_of(wrap(deep)));
  EXPECT_NO_THROW(graph_of(wrap(R"({"op": "repeat", "spacing": [1, 1, 1], "count": [100, 100, 100], "children": [)" +
                                sphere(0.2f) + "]}")));
}

TEST(GraphModifiers, TheLibrarysOneFieldOperatorsAreAccepted) {
  for (const char* op : {"opRound\", \"r", "opOnion\", \"t", "dilate\", \"r", "erode\", \"r", "onion\", \"t"})
    EXPECT_NO_THROW(graph_of(wrap(std::string(R"({"op": ")") + op + R"(": 0.1, "children": [)" + sphere(1) + "]}")))
        << op;
  EXPECT_NO_THROW(graph_of(wrap(R"({"op": "opExtrude", "h": 0.2, "children": [{"sdf": "sd2Hexagon", "r": 1}]})")));
}

TEST(GraphModifiers, EachModifierIsAFrameOfItsOwnInBothEvaluators) {
  const SceneGraph g = graph_of(wrap(R"({"op": "opUnion", "children": [)" + sphere(0.5f) +
                                     R"(, {"op": "twist", "k": 1, "children": [{"op": "round", "r": 0.1, "children": [)" +
                                     sphere(0.2f) + "]}]}]}"));
  const std::vector<int> frames = graph_frames(g);
  ASSERT_EQ(frames.size(), 5u);
  EXPECT_EQ(frames[0], -1);  // the first sphere, in the world
  EXPECT_EQ(frames[1], 2);   // the inner sphere, in the round's frame
  EXPECT_EQ(frames[2], 3);   // the round, in the twist's
  const std::string glsl = graph_map_inline(g);
  EXPECT_NE(glsl.find("vec2 msFrame2(vec3 p)"), std::string::npos);
  EXPECT_NE(glsl.find("vec2 msFrame3(vec3 p)"), std::string::npos);
  EXPECT_LT(glsl.find("msFrame2(vec3"), glsl.find("msFrame3(vec3"));  // inner first
  const GraphBuffers b = graph_buffers(g);
  EXPECT_EQ(b.frames, 2);
  // begin twist, begin round, sphere, end round, end twist: units of 5 and 3.
  EXPECT_EQ(b.nodes[4 * 3 + 2], 5u);
  EXPECT_EQ(b.nodes[4 * 2 + 2], 3u);
}

}  // namespace
}  // namespace ms::test

namespace ms::test {
namespace {

// Each modifier's begin and end functions are in the library, taking the
// point (and the child's value) then exactly the vocabulary's parameters.
TEST(GraphModifiers, MatchTheLibrarysSignatures) {
  std::string text;
  for (const char* f : {"modifiers.glsl", "domain.glsl", "combinators.glsl"})
    text += read_file(source_dir() / "sdf_shaders" / f);
  const std::regex sig(R"((?:vec3|float) ((?:dom|op)[A-Z]\w*)\(([^)]*)\))");
  std::map<std::string, std::string> lib;
  for (std::sregex_iterator it(text.begin(), text.end(), sig), end; it != end; ++it)
    lib[(*it)[1]] = std::regex_replace(std::string((*it)[2]), std::regex(R"(\s+)"), " ");
  for (const GraphUnary& u : graph_unaries()) {
    std::string params;
    for (const GraphParam& p : u.params)
      params += std::string(", ") + (p.size == 1 ? "float " : "vec" + std::to_string(p.size) + " ") + std::string(p.name);
    if (!u.begin.empty()) {
      ASSERT_TRUE(lib.count(std::string(u.begin))) << u.begin;
      EXPECT_EQ(lib[std::string(u.begin)], "vec3 p" + params + (u.copies ? ", float t, out float n" : "")) << u.name;
    }
    if (!u.end.empty()) {
      ASSERT_TRUE(lib.count(std::string(u.end))) << u.end;
      EXPECT_EQ(lib[std::string(u.end)], std::string("float d") + (u.end_point ? ", vec3 p" : "") + params) << u.name;
    }
    EXPECT_FALSE(u.begin.empty() && u.end.empty()) << u.name;
  }
}

}  // namespace
}  // namespace ms::test
