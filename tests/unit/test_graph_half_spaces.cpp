// Half-spaces in the scene graph: sdPlane and sdSlab (bounds per axis, any
// end open) have boxes infinite only where they are open, which an
// intersection or a subtraction cuts down to a finite graph; an unbounded
// graph is refused at the node that makes it so.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "core/error.h"
#include "graph_of.h"
#include "io/json_doc.h"
#include "scene/graph_build.h"

namespace {

constexpr float kInf = INFINITY;

using ms::test::graph_of;
using ms::test::graph_error;

std::string node(const std::string& body) { return "{\"root\": " + body + "}"; }

// A half-space as the second child of `op` (its name and parameters), the
// first a unit box.
ms::SceneGraph cut(const std::string& op, const std::string& half_space) {
  return graph_of(node("{\"op\": " + op + ", \"children\": [{\"sdf\": \"sdBox\", \"b\": [1, 1, 1]}, " +
                       half_space + "]}"));
}

// A half-space's own box: alone it would be refused as unbounded, so it
// is the second child of an intersection with a large sphere.
ms::GraphBox leaf_box(const std::string& half_space) {
  return graph_of(node("{\"op\": \"opIntersection\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 100}, " +
                       half_space + "]}"))
      .nodes[1]
      .box;
}

void expect_box(const ms::GraphBox& b, glm::vec3 lo, glm::vec3 hi) {
  for (int i = 0; i < 3; ++i) {
    if (std::isinf(lo[i])) EXPECT_EQ(b.min[i], lo[i]) << "min " << "xyz"[i];
    else EXPECT_NEAR(b.min[i], lo[i], 1e-3f) << "min " << "xyz"[i];
    if (std::isinf(hi[i])) EXPECT_EQ(b.max[i], hi[i]) << "max " << "xyz"[i];
    else EXPECT_NEAR(b.max[i], hi[i], 1e-3f) << "max " << "xyz"[i];
  }
}

TEST(GraphHalfSpaces, ASlabsBoxIsInfiniteOnlyWhereItIsOpen) {
  expect_box(leaf_box("{\"sdf\": \"sdSlab\", \"x\": [-1, 2], \"z\": [0.5, null]}"), {-1, -kInf, 0.5f}, {2, kInf, kInf});
}

TEST(GraphHalfSpaces, AnAxisAlignedPlaneBoundsItsAxis) {
  // dot(p, n) + w <= 0: y <= 0.5, then y >= 0.2.
  expect_box(leaf_box("{\"sdf\": \"sdPlane\", \"n\": [0, 1, 0], \"w\": -0.5}"), {-kInf, -kInf, -kInf},
             {kInf, 0.5f, kInf});
  expect_box(leaf_box("{\"sdf\": \"sdPlane\", \"n\": [0, -1, 0], \"w\": 0.2}"), {-kInf, 0.2f, -kInf},
             {kInf, kInf, kInf});
  // A tilted plane bounds nothing.
  expect_box(leaf_box("{\"sdf\": \"sdPlane\", \"n\": [0.6, 0.8, 0], \"w\": 0}"),
             {-kInf, -kInf, -kInf}, {kInf, kInf, kInf});
}

TEST(GraphHalfSpaces, ARotatedSlabKeepsItsFiniteAxisFinite) {
  // z in [0, 1], turned 90 degrees about x: y in [-1, 0]; x and z open.
  expect_box(leaf_box("{\"sdf\": \"sdSlab\", \"z\": [0, 1], \"rotate\": [1, 0, 0, 90], \"translate\": [0, 3, 0]}"),
             {-kInf, 2, -kInf}, {kInf, 3, kInf});
}

TEST(GraphHalfSpaces, AnIntersectionCutsTheBoxAndASubtractionKeepsItsShape) {
  expect_box(cut("\"opIntersection\"", "{\"sdf\": \"sdSlab\", \"y\": [null, 0.25]}").root_node().box, {-1, -1, -1},
             {1, 0.25f, 1});
  expect_box(cut("\"opIntersection\"", "{\"sdf\": \"sdPlane\", \"n\": [0, 0, -1], \"w\": 0.5}").root_node().box,
             {-1, -1, 0.5f}, {1, 1, 1});
  expect_box(cut("\"opSubtraction\"", "{\"sdf\": \"sdPlane\", \"n\": [0.6, 0.8, 0], \"w\": 0.1}").root_node().box,
             {-1, -1, -1}, {1, 1, 1});
  expect_box(cut("\"opSmoothIntersection\", \"k\": 0.1",
                 "{\"sdf\": \"sdSlab\", \"x\": [0, null], \"z\": [-0.5, 0.5]}")
                 .root_node()
                 .box,
             {0, -1, -0.5f}, {1, 1, 0.5f});
}

TEST(GraphHalfSpaces, AnUnboundedGraphNamesTheNodeThatMakesIt) {
  const std::string sphere = "{\"sdf\": \"sdSphere\", \"r\": 1}";
  const std::string plane = "{\"sdf\": \"sdPlane\", \"n\": [0, 1, 0], \"w\": 0}";
  EXPECT_EQ(graph_error(node("{\"op\": \"opUnion\", \"children\": [" + sphere + ", " + plane + "]}")),
            "g.json:1: /root/children/1: the graph is unbounded: an infinite sdPlane not cut by an intersection "
            "(intersect it with a bounded shape or subtract it from one; ground planes go in [[planes]])");
  // What a subtraction cuts from is what bounds it; deeper down, the slab.
  const std::string slab = "{\"sdf\": \"sdSlab\", \"y\": [0, 1]}";
  const std::string e = graph_error(node("{\"op\": \"opUnion\", \"children\": [" + sphere +
                                      ", {\"op\": \"opSubtraction\", \"children\": [" + slab + ", " + sphere + "]}, " +
                                      plane + "]}"));
  EXPECT_NE(e.find("/root/children/1/children/0: the graph is unbounded: an infinite sdSlab"), std::string::npos) << e;
  // Subtracted from a bounded shape, both are fine.
  EXPECT_TRUE(cut("\"opSubtraction\"", slab).root_node().box.finite());
}

TEST(GraphHalfSpaces, BadBoundsAndNormalsAreOneLineAtTheirValue) {
  const auto slab = [](const std::string& params) { return node("{\"sdf\": \"sdSlab\"" + params + "}"); };
  EXPECT_NE(graph_error(slab("")).find("/root: it bounds no axis"), std::string::npos);
  EXPECT_NE(graph_error(slab(", \"x\": [null, null]")).find("/root: it bounds no axis"), std::string::npos);
  EXPECT_NE(graph_error(slab(", \"x\": [1, 0]")).find("/root/x: 'x' must have min <= max"), std::string::npos);
  EXPECT_NE(graph_error(slab(", \"y\": [1]")).find("/root/y: 'y' must be [min, max]"), std::string::npos);
  EXPECT_NE(graph_error(slab(", \"z\": [0, 1e25]")).find("/root/z/1: each end of 'z' must be within 1e+18"),
            std::string::npos);
  EXPECT_NE(graph_error(slab(", \"z\": [0, \"top\"]")).find("/root/z/1: each end of 'z' must be a number"),
            std::string::npos);
  // A longer normal would make the field 2-Lipschitz, against its L = 1.
  EXPECT_NE(graph_error(node("{\"sdf\": \"sdPlane\", \"n\": [0, 2, 0], \"w\": 0}")).find("/root/n: 'n' must have length 1 (it has 2)"),
            std::string::npos);
}

TEST(GraphHalfSpaces, AnInlineTableOpensAnEndWithInf) {
  const toml::table t = toml::parse(
      "[root]\nop = \"opIntersection\"\nchildren = [{ sdf = \"sdSphere\", r = 1.0 },\n"
      "  { sdf = \"sdSlab\", y = [-inf, 0.5] }, { sdf = \"sdSlab\", x = [-0.25, inf] }]\n");
  std::vector<ms::Material> materials{ms::Material{"m"}};
  const ms::SceneGraph g = ms::load_graph_table(t, "s.toml", materials);
  expect_box(g.root_node().box, {-0.25f, -1, -1}, {1, 0.5f, 1});
  // The wrong infinity for its end is not a number.
  const toml::table bad = toml::parse("[root]\nsdf = \"sdSlab\"\ny = [inf, 0.5]\n");
  try {
    ms::load_graph_table(bad, "s.toml", materials);
    ADD_FAILURE() << "no error";
  } catch (const ms::Error& e) {
    EXPECT_NE(std::string(e.what()).find("scene.graph/root/y/0: each end of 'y' must be a finite number"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
