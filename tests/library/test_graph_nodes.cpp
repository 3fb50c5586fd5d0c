// The scene graph's modifiers hold the bound and box the builder derives
// for them (docs/scene-graph.md, "Modifiers and profiles"): each node's
// inline map() is sampled on the GPU at 100,000 pairs of points, whose
// values differ by no more than the node's Lipschitz bound times their
// distance, and its surface (found along rays by bisection) and every
// point where it is negative lie inside the node's box.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include <glm/geometric.hpp>

#include "gl/context.h"
#include "gpu_eval.h"
#include "graph_of.h"
#include "shader/graph_glsl.h"

namespace ms::test {
namespace {

const std::string kShaders = std::string(MARCH_SOURCE_DIR) + "/sdf_shaders";

struct NodeCase {
  const char* name;
  const char* json;  // the root node
};

const NodeCase kCases[] = {
    {"twist", R"({"op": "twist", "k": 2, "children": [{"sdf": "sdBox", "b": [0.3, 0.8, 0.15]}]})"},
    {"twist about z", R"({"op": "twist", "k": -1.5, "axis": [0, 0, 1], "children": [{"sdf": "sdBox", "b": [0.5, 0.1, 0.7], "translate": [0.1, 0, 0]}]})"},
    {"bend", R"({"op": "bend", "k": 1.2, "children": [{"sdf": "sdBox", "b": [0.7, 0.1, 0.2]}]})"},
    {"elongate", R"({"op": "elongate", "h": [0.3, 0, 0.2], "children": [{"sdf": "sdTorus", "t": [0.4, 0.1]}]})"},
    {"repeat", R"({"op": "repeat", "spacing": [0.5, 0, 0.45], "count": [2, 0, 1], "children": [{"sdf": "sdBox", "b": [0.2, 0.15, 0.1], "translate": [0.08, 0, 0]}]})"},
    {"repeat, copies overlapping", R"({"op": "repeat", "spacing": [0.3, 0.3, 0], "count": [2, 1, 0], "children": [{"sdf": "sdSphere", "r": 0.25}]})"},
    {"polar", R"({"op": "polar", "count": 7, "radius": 0.5, "children": [{"sdf": "sdCapsule", "a": [0, -0.2, 0], "b": [0.2, 0.2, 0.1], "r": 0.08}]})"},
    {"mirror", R"({"op": "mirror", "n": [0.6, 0, 0.8], "w": 0.1, "children": [{"sdf": "sdBox", "b": [0.3, 0.2, 0.25], "translate": [0.2, 0, 0.3]}]})"},
    {"symmetry", R"({"op": "symmetry", "axes": [1, 1, 0], "children": [{"sdf": "sdTorus", "t": [0.3, 0.08], "translate": [0.3, 0.2, 0]}]})"},
    {"scale", R"({"op": "scale", "s": [1.6, 0.5, 1], "children": [{"sdf": "sdBox", "b": [0.3, 0.3, 0.3], "rotate": [1, 1, 0, 30]}]})"},
    {"round", R"({"op": "round", "r": 0.1, "children": [{"sdf": "sdBox", "b": [0.4, 0.2, 0.3]}]})"},
    {"erode", R"({"op": "erode", "r": 0.08, "children": [{"sdf": "sdBox", "b": [0.4, 0.2, 0.3]}]})"},
    {"shell", R"({"op": "shell", "thickness": 0.06, "children": [{"sdf": "sdTorus", "t": [0.4, 0.15]}]})"},
    {"onion", R"({"op": "onion", "t": 0.03, "children": [{"sdf": "sdSphere", "r": 0.5}]})"},
    {"extrude", R"({"op": "extrude", "h": 0.5, "r": 0.05, "children": [{"sdf": "sd2Star", "r": 0.6, "ri": 0.3, "n": 5, "rotate": 20}]})"},
    {"polygon", R"({"op": "extrude", "h": 0.4, "r": 0.03, "children": [{"sdf": "sd2Polygon", "v": [[-0.6, -0.2], [0.1, -0.2], [0.1, -0.5], [0.6, 0.05], [0.1, 0.55], [0.1, 0.25], [-0.6, 0.25]]}]})"},
    {"opExtrude", R"({"op": "opExtrude", "h": 0.2, "children": [{"sdf": "sd2Hexagon", "r": 0.4}]})"},
    {"revolve", R"({"op": "revolve", "offset": 0.4, "children": [{"sdf": "sd2Box", "b": [0.1, 0.25], "translate": [0.05, 0]}]})"},
    {"opBlend", R"({"op": "opBlend", "t": 0.3, "children": [{"sdf": "sdSphere", "r": 0.5}, {"sdf": "sdBox", "b": [0.4, 0.3, 0.6], "translate": [0.2, 0, 0]}]})"},
    {"nested", R"({"op": "twist", "k": 1, "translate": [0.1, 0, 0], "children": [{"op": "round", "r": 0.04, "children": [{"op": "repeat", "spacing": [0, 0.4, 0], "count": [0, 2, 0], "children": [{"sdf": "sdBox", "b": [0.3, 0.1, 0.1]}]}]}]})"},
};

class GraphNodeClaims : public ::testing::TestWithParam<NodeCase> {};

TEST_P(GraphNodeClaims, HoldTheirBoundAndBox) {
  std::unique_ptr<Context> ctx = create_headless_context(Backend::automatic);
  const SceneGraph g = graph_of(std::string(R"({"root": )") + GetParam().json + "}");
  const GraphNode& n = g.root_node();
  std::string map = graph_map_inline(g);
  map.erase(0, map.find('\n') + 1);  // its #include "aov.glsl": the counters are not wanted here
  const GpuCase c(kShaders, {"map(p).x", "false", "false", "0.0", "vec3(0.0)", "#define MS_COUNT_PRIMS(n)\n" + map});
  const glm::vec3 half = 0.5f * (n.box.max - n.box.min), centre = 0.5f * (n.box.max + n.box.min);
  Box box{centre - 1.5f * half - 0.1f, centre + 1.5f * half + 0.1f};
  const float diag = glm::length(box.hi - box.lo);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int pairs = 100000;
  std::vector<glm::vec3> pts;
  for (int i = 0; i < pairs; ++i) {
    const glm::vec3 a = box.lo + glm::vec3(u(rng), u(rng), u(rng)) * (box.hi - box.lo);
    glm::vec3 d = glm::vec3(u(rng), u(rng), u(rng)) - 0.5f;
    d = glm::normalize(d + glm::vec3(1e-6f)) * (1e-3f + 0.1f * diag * u(rng) * u(rng));
    pts.push_back(a);
    pts.push_back(a + d);
  }
  const std::vector<Sample> s = c.eval(pts);
  ASSERT_EQ(s.size(), pts.size());
  int steep = 0, outside_negative = 0, negative = 0;
  double worst = 0.0;
  const GraphBox tight = box_grow(n.box, 1e-4f * diag);
  const auto in_box = [&](glm::vec3 p) {
    return glm::all(glm::greaterThanEqual(p, tight.min)) && glm::all(glm::lessThanEqual(p, tight.max));
  };
  for (int i = 0; i < pairs; ++i) {
    const float fa = s[2 * i].f, fb = s[2 * i + 1].f;
    const double dist = glm::length(pts[2 * i + 1] - pts[2 * i]);
    const double slope = std::fabs(double(fa) - fb) / dist;
    worst = std::max(worst, slope);
    steep += std::fabs(double(fa) - fb) > n.lipschitz * dist * (1.0 + 1e-3) + 2e-5;
    for (int k = 0; k < 2; ++k) {
      negative += s[2 * i + k].f < 0.0f;
      outside_negative += s[2 * i + k].f < -1e-5f && !in_box(pts[2 * i + k]);
    }
  }
  EXPECT_EQ(steep, 0) << "largest slope " << worst << " against the bound " << n.lipschitz;
  EXPECT_EQ(outside_negative, 0);
  EXPECT_GT(negative, 100) << "the samples must reach inside the shape";
  const std::vector<glm::vec3> zeros = c.zeros(box, 48, 192, 3);
  EXPECT_GT(zeros.size(), 200u);
  int stray = 0;
  for (glm::vec3 z : zeros) stray += !in_box(z);
  EXPECT_EQ(stray, 0) << "of " << zeros.size() << " surface points";
}

INSTANTIATE_TEST_SUITE_P(, GraphNodeClaims, ::testing::ValuesIn(kCases), [](const ::testing::TestParamInfo<NodeCase>& i) {
  std::string s;
  for (const char* c = i.param.name; *c; ++c) s += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
  return s;
});

}  // namespace
}  // namespace ms::test
