// Pruning is exact (docs/scene-graph.md): on random graphs using every
// combinator, smooth blends, subtractions and transforms, and on the
// repository's graph scenes, the pruned grid gives the image and the step
// counts of --no-prune, whose every cell runs the whole graph.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "dispatch.h"
#include "image_diff.h"
#include "io/image_io.h"
#include "graph_scene.h"
#include "run.h"
#include "scene/graph_vocab.h"

namespace ms::test {
namespace {

// Bounded primitives whose parameters a uniform draw keeps valid, with a
// generator for each parameter list (the library's preconditions: a tube
// thinner than its ring, a rounding within the box).
struct Shape {
  const char* sdf;
  std::string (*params)(std::mt19937& rng);
};

float u(std::mt19937& rng, float lo, float hi) {
  return lo + (hi - lo) * static_cast<float>(rng() % 10000) / 10000.0f;
}
std::string num(float v) { return std::to_string(v); }
std::string vec(std::mt19937& rng, float lo, float hi, int n = 3) {
  std::string s = "[";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + num(u(rng, lo, hi));
  return s + "]";
}

const Shape kShapes[] = {
    {"sdSphere", [](std::mt19937& r) { return "\"r\": " + num(u(r, 0.2f, 0.5f)); }},
    {"sdBox", [](std::mt19937& r) { return "\"b\": " + vec(r, 0.1f, 0.4f); }},
    {"sdRoundBox", [](std::mt19937& r) { return "\"b\": " + vec(r, 0.2f, 0.4f) + ", \"r\": " + num(u(r, 0.0f, 0.1f)); }},
    {"sdTorus", [](std::mt19937& r) { return "\"t\": [" + num(u(r, 0.25f, 0.4f)) + ", " + num(u(r, 0.05f, 0.15f)) + "]"; }},
    {"sdCylinder", [](std::mt19937& r) { return "\"r\": " + num(u(r, 0.1f, 0.3f)) + ", \"h\": " + num(u(r, 0.1f, 0.4f)); }},
    {"sdCapsule", [](std::mt19937& r) { return "\"a\": " + vec(r, -0.3f, 0.3f) + ", \"b\": " + vec(r, -0.3f, 0.3f) + ", \"r\": " + num(u(r, 0.05f, 0.2f)); }},
    {"sdOctahedron", [](std::mt19937& r) { return "\"s\": " + num(u(r, 0.2f, 0.5f)); }},
    {"sdEllipsoid", [](std::mt19937& r) { return "\"r\": " + vec(r, 0.15f, 0.4f); }},
    {"sdHexPrism", [](std::mt19937& r) { return "\"h\": " + vec(r, 0.1f, 0.3f, 2); }},
    {"sdCone", [](std::mt19937& r) { return "\"r\": " + num(u(r, 0.1f, 0.3f)) + ", \"h\": " + num(u(r, 0.2f, 0.5f)); }},
    {"sdLink", [](std::mt19937& r) { return "\"le\": " + num(u(r, 0.05f, 0.2f)) + ", \"r1\": " + num(u(r, 0.15f, 0.25f)) + ", \"r2\": " + num(u(r, 0.03f, 0.08f)); }},
    {"sdDodecahedron", [](std::mt19937& r) { return "\"r\": " + num(u(r, 0.15f, 0.35f)); }},
};

std::string transform(std::mt19937& rng) {
  std::string s;
  if (rng() % 2) s += ", \"translate\": " + vec(rng, -0.6f, 0.6f);
  if (rng() % 2) s += ", \"rotate\": [" + num(u(rng, -1, 1)) + ", " + num(u(rng, 0.1f, 1)) + ", " + num(u(rng, -1, 1)) + ", " + num(u(rng, -180, 180)) + "]";
  if (rng() % 3 == 0) s += ", \"scale\": " + num(u(rng, 0.6f, 1.5f));
  if (rng() % 2) s += std::string(", \"material\": \"") + (rng() % 2 ? "a" : "b") + "\"";
  return s;
}

// An operator's parameters: lengths small against the shapes, a weight in
// [0, 1], n a count.
std::string op_params(const GraphOperator& op, std::mt19937& rng) {
  std::string s;
  for (const GraphParam& p : op.params)
    s += ", \"" + std::string(p.name) + "\": " +
         (p.length ? num(u(rng, 0.02f, 0.15f)) : p.fraction ? num(u(rng, 0.0f, 1.0f)) : num(static_cast<float>(2 + rng() % 3)));
  return s;
}

std::string random_node(std::mt19937& rng, int depth, int& op_index) {
  if (depth == 0 || rng() % 4 == 0) {
    const Shape& sh = kShapes[rng() % std::size(kShapes)];
    return "{\"sdf\": \"" + std::string(sh.sdf) + "\", " + sh.params(rng) + transform(rng) + "}";
  }
  // Every combinator in turn, so 20 graphs of about 4 each use them all.
  const auto ops = graph_operators();
  const GraphOperator& op = ops[static_cast<std::size_t>(op_index++) % ops.size()];
  std::string kids;
  const int n = 2 + static_cast<int>(rng() % 3);
  for (int i = 0; i < n; ++i) kids += (i ? ", " : "") + random_node(rng, depth - 1, op_index);
  return "{\"op\": \"" + std::string(op.name) + "\"" + op_params(op, rng) + transform(rng) + ", \"children\": [" + kids + "]}";
}

const std::string kScene = graph_test_scene("[1.6, 1.4, -2.6]", "[0.0, 0.2, 0.0]", 45.0, 1.2);

struct Rendered {
  Image img;
  double sdf_evals = 0.0;  // summed over the pixels
  std::string log;         // stderr
};

Rendered render(const std::filesystem::path& scene, const std::filesystem::path& out, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render", scene.string(), "--size", "48x27", "--aov", "steps,cost",
                                   "--graph-eval", "interpreter", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  Rendered x{read_image(out), 0.0, r.err};
  for (float v : channel(x.img, "sdf_evals")) x.sdf_evals += v;
  return x;
}

// The colour within 1/255, the same primary steps, map() calls within 1%
// (a far cell outside the bounds steps a shadow ray by a lower bound).
void expect_same(const Rendered& pruned, const Rendered& whole, const std::string& what) {
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float> a = channel(pruned.img, c), b = channel(whole.img, c);
    ASSERT_EQ(a.size(), b.size()) << what;
    ASSERT_FALSE(a.empty()) << what;
    double m = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, static_cast<double>(std::fabs(a[i] - b[i])));
    EXPECT_LE(m, 1.0 / 255 + 1e-6) << what << " channel " << c;
  }
  EXPECT_NEAR(pruned.sdf_evals, whole.sdf_evals, 0.01 * whole.sdf_evals) << what;
  EXPECT_EQ(channel(pruned.img, "steps"), channel(whole.img, "steps")) << what;
}

class GraphPrune : public BothDispatches {};

// Twenty-four graphs, each taking the combinators in turn, so that every
// one of them, and every pruning rule, is met in several.
TEST_P(GraphPrune, RandomGraphsGiveTheImageAndStepsOfTheWholeGraph) {
  TempDir dir;
  std::mt19937 rng(20261205);
  int op_index = 0;
  const int graphs = dispatch() == "fragment" ? 24 : 4;  // compute: the first four again
  for (int g = 0; g < graphs; ++g) {
    // A small sphere at the origin keeps every intersection's box non-empty.
    const std::string root = "{\"op\": \"opUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 0.05}, " +
                             random_node(rng, 3, op_index) + "]}";
    write_file(dir / "g.json", "{\"root\": " + root + "}");
    write_file(dir / "s.toml", kScene);
    const Rendered pruned = render(dir / "s.toml", dir / "p.exr", with_dispatch({}));
    const Rendered whole = render(dir / "s.toml", dir / "w.exr", with_dispatch({"--no-prune"}));
    expect_same(pruned, whole, "graph " + std::to_string(g) + " (" + std::to_string(root.size()) + " bytes): " + root.substr(0, 160));
    if (HasFailure()) return;
  }
  EXPECT_GE(op_index, static_cast<int>(graph_operators().size()));
}

INSTANTIATE_BOTH_DISPATCHES(GraphPrune);

TEST(GraphPruneScenes, EveryGraphSceneOfTheRepositoryPrunesExactly) {
  TempDir dir;
  for (const char* scene : {"tests/data/graph/part.toml", "scenes/part.toml", "scenes/molecule.toml"}) {
    const Rendered pruned = render(source_dir() / scene, dir / "p.exr", {});
    const Rendered whole = render(source_dir() / scene, dir / "w.exr", {"--no-prune"});
    expect_same(pruned, whole, scene);
  }
}

// The seam combinators' rules, on a box and a sphere crossing its edge
// joined by each: exact (the image and steps of --no-prune, where a wrong
// reach shows along the seam), and cutting lists, counted in instructions:
// the fine cells' mean list (render -v) is shorter than the 3-instruction
// program, while the pipe, which has no rule, keeps all 3 everywhere.
TEST(GraphPruneSeams, TheSeamCombinatorsRulesAreExactAndShortenTheLists) {
  TempDir dir;
  const std::pair<const char*, const char*> ops[] = {
      {"opUnionColumns", "\"r\": 0.3, \"n\": 3"}, {"opUnionStairs", "\"r\": 0.3, \"n\": 3"},
      {"opEngrave", "\"r\": 0.2"}, {"opGroove", "\"ra\": 0.15, \"rb\": 0.15"},
      {"opTongue", "\"ra\": 0.15, \"rb\": 0.15"}, {"opPipe", "\"r\": 0.1"}};
  for (const auto& [op, params] : ops) {
    write_file(dir / "g.json", std::string("{\"root\": {\"op\": \"") + op + "\", " + params +
                                   ", \"children\": [{\"sdf\": \"sdBox\", \"b\": [0.5, 0.5, 0.5]}, "
                                   "{\"sdf\": \"sdSphere\", \"r\": 0.3, \"translate\": [0.5, 0.5, 0]}]}}");
    const Rendered pruned = render(dir / "g.json", dir / "p.exr", {"-v"});
    const Rendered whole = render(dir / "g.json", dir / "w.exr", {"--no-prune"});
    expect_same(pruned, whole, op);
    const std::size_t at = pruned.log.find("mean list ");
    ASSERT_NE(at, std::string::npos) << op << ": " << pruned.log;
    const double mean = std::stod(pruned.log.substr(at + 10));
    EXPECT_NE(pruned.log.find("instructions (of 3)"), std::string::npos) << op << ": " << pruned.log;
    if (std::string(op) == "opPipe") EXPECT_EQ(mean, 3.0) << op;
    else EXPECT_LT(mean, 2.5) << op;
  }
}

}  // namespace
}  // namespace ms::test
