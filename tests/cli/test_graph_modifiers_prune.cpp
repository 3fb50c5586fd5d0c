// Pruning stays exact through the graph's modifiers and profiles
// (docs/scene-graph.md, "Modifiers"): on thirty random graphs that use
// every modifier and profile, the pruned grid gives the image and the
// step counts of --no-prune, and the interpreter gives the inline map()'s
// image.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "dispatch.h"
#include "image_diff.h"
#include "io/image_io.h"
#include "graph_scene.h"
#include "run.h"
#include "scene/graph_unary.h"

namespace ms::test {
namespace {

float u(std::mt19937& rng, float lo, float hi) { return lo + (hi - lo) * static_cast<float>(rng() % 10000) / 10000.0f; }
std::string num(float v) { return std::to_string(v); }
std::string vec(std::mt19937& rng, float lo, float hi, int n = 3) {
  std::string s = "[";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + num(u(rng, lo, hi));
  return s + "]";
}

std::string solid(std::mt19937& rng) {
  switch (rng() % 4) {
    case 0: return R"({"sdf": "sdSphere", "r": )" + num(u(rng, 0.1f, 0.3f)) + "}";
    case 1: return R"({"sdf": "sdBox", "b": )" + vec(rng, 0.08f, 0.25f) + "}";
    case 2: return R"({"sdf": "sdTorus", "t": [)" + num(u(rng, 0.15f, 0.25f)) + ", " + num(u(rng, 0.03f, 0.08f)) + "]}";
    default: return R"({"sdf": "sdCapsule", "a": )" + vec(rng, -0.2f, 0.2f) + R"(, "b": )" + vec(rng, -0.2f, 0.2f) +
                    R"(, "r": )" + num(u(rng, 0.04f, 0.1f)) + "}";
  }
}

std::string profile(std::mt19937& rng) {
  const std::string t = R"(, "translate": )" + vec(rng, -0.05f, 0.05f, 2) + R"(, "rotate": )" + num(u(rng, -90, 90));
  switch (rng() % 5) {
    case 0: return R"({"sdf": "sd2Circle", "r": )" + num(u(rng, 0.05f, 0.2f)) + t + "}";
    case 1: return R"({"sdf": "sd2Box", "b": )" + vec(rng, 0.05f, 0.2f, 2) + t + "}";
    case 2: return R"({"sdf": "sd2Star", "r": 0.2, "ri": 0.1, "n": 5)" + t + "}";
    case 3: return R"({"sdf": "sd2Polygon", "v": [[-0.2, -0.1], [0.05, -0.1], [0.05, -0.2], [0.2, 0.02], [0.05, 0.2], [0.05, 0.1], [-0.2, 0.1]])" + t + "}";
    default:
      return R"({"op": "opSubtraction", "children": [{"sdf": "sd2Hexagon", "r": 0.2}, {"sdf": "sd2Circle", "r": 0.08}])" + t + "}";
  }
}

// Modifier `m` (an index into graph_unaries()) over a random child.
std::string modifier(std::mt19937& rng, std::string_view m, int depth);

std::string node(std::mt19937& rng, int depth, int& next) {
  const auto all = graph_unaries();
  if (depth == 0 || rng() % 5 == 0) return solid(rng);
  if (rng() % 3 == 0) {
    std::string kids = node(rng, depth - 1, next) + ", " + node(rng, depth - 1, next);
    const char* op = rng() % 2 ? R"("opSmoothUnion", "k": 0.05)" : R"("opUnion")";
    return R"({"op": )" + std::string(op) + R"(, "translate": )" + vec(rng, -0.2f, 0.2f) + R"(, "children": [)" + kids + "]}";
  }
  // Every modifier in turn.
  return modifier(rng, all[static_cast<std::size_t>(next++) % all.size()].name, depth);
}

std::string modifier(std::mt19937& rng, std::string_view m, int depth) {
  int next = static_cast<int>(rng() % 100);
  const std::string head = R"({"op": ")" + std::string(m) + R"(", "translate": )" + vec(rng, -0.3f, 0.3f);
  const std::string child = node(rng, depth - 1, next);
  const auto with = [&](const std::string& params, const std::string& kid) {
    return head + ", " + params + R"(, "children": [)" + kid + "]}";
  };
  if (m == "twist") return with(R"("k": )" + num(u(rng, -3, 3)), child);
  if (m == "bend") return with(R"("k": )" + num(u(rng, -2, 2)), child);
  if (m == "elongate") return with(R"("h": )" + vec(rng, 0.0f, 0.15f), child);
  if (m == "repeat") return with(R"("spacing": [0.35, 0, 0.3], "count": [1, 0, 1])", child);
  if (m == "polar") return with(R"("count": 5, "radius": 0.25)", solid(rng));
  if (m == "mirror") return with(R"("n": [0.6, 0.8, 0], "w": 0.05)", child);
  if (m == "symmetry") return with(R"("axes": [1, 0, 1])", child);
  if (m == "scale") return with(R"("s": )" + vec(rng, 0.5f, 1.5f), child);
  if (m == "extrude") return with(R"("h": 0.3, "r": 0.02)", profile(rng));
  if (m == "opExtrude") return with(R"("h": 0.12)", profile(rng));
  if (m == "revolve") return with(R"("offset": 0.15)", profile(rng));
  if (m == "shell") return with(R"("thickness": 0.04)", child);
  if (m == "onion" || m == "opOnion") return with(R"("t": 0.02)", child);
  return with(R"("r": )" + num(u(rng, 0.01f, 0.05f)), child);  // round, dilate, opRound, erode
}

const std::string kScene = graph_test_scene("[1.6, 1.4, -2.6]", "[0.0, 0.0, 0.0]", 45.0, 1.2);

Image render(const std::filesystem::path& dir, const std::string& name, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render", (dir / "s.toml").string(), "--size", "48x27", "--aov", "steps",
                                   "-o", (dir / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(dir / name);
}

double max_diff(const Image& a, const Image& b) {
  double m = 0.0;
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float> x = channel(a, c), y = channel(b, c);
    if (x.size() != y.size() || x.empty()) return 1e9;
    for (std::size_t i = 0; i < x.size(); ++i) m = std::max(m, static_cast<double>(std::fabs(x[i] - y[i])));
  }
  return m;
}

class GraphModifierPrune : public BothDispatches {};

TEST_P(GraphModifierPrune, ThirtyRandomGraphsGiveTheWholeGraphsImage) {
  TempDir dir;
  std::mt19937 rng(20261207);
  int next = 0;
  const int graphs = dispatch() == "fragment" ? 30 : 3;
  write_file(dir / "s.toml", kScene);
  for (int g = 0; g < graphs; ++g) {
    const std::string root = R"({"op": "opUnion", "children": [{"sdf": "sdSphere", "r": 0.05}, )" + node(rng, 3, next) +
                             ", " + node(rng, 2, next) + "]}";
    write_file(dir / "g.json", "{\"root\": " + root + "}");
    const std::string what = "graph " + std::to_string(g) + ": " + root.substr(0, 200);
    const Image pruned = render(dir.path(), "p.exr", with_dispatch({"--graph-eval", "interpreter"}));
    const Image whole = render(dir.path(), "w.exr", with_dispatch({"--graph-eval", "interpreter", "--no-prune"}));
    EXPECT_LE(max_diff(pruned, whole), 1.0 / 255 + 1e-6) << what;
    EXPECT_EQ(channel(pruned, "steps"), channel(whole, "steps")) << what;
    if (dispatch() == "fragment" && g < 10) {
      // Another program: the same field, rounded differently at most at a
      // grazing pixel or two.
      const Image inl = render(dir.path(), "i.exr", with_dispatch({"--graph-eval", "inline"}));
      const std::vector<float> a = channel(inl, "G"), b = channel(whole, "G");
      int off = 0;
      for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) off += std::fabs(a[i] - b[i]) > 2.0f / 255;
      EXPECT_LE(off, 3) << what;
    }
    if (HasFailure()) return;
  }
  if (dispatch() == "fragment") EXPECT_GE(next, static_cast<int>(graph_unaries().size()));
}

INSTANTIATE_BOTH_DISPATCHES(GraphModifierPrune);

// A row of n small spheres 0.2 apart along x, centred: a child worth
// pruning inside.
std::string row(int n, float y = 0.0f) {
  std::string kids;
  for (int i = 0; i < n; ++i)
    kids += std::string(i ? ", " : "") + R"({"sdf": "sdSphere", "r": 0.06, "translate": [)" +
            num(0.2f * (static_cast<float>(i) - 0.5f * static_cast<float>(n - 1))) + ", " + num(y) + ", 0]}";
  return R"({"op": "opUnion", "children": [)" + kids + "]}";
}
std::string row2(int n) {  // the same as a profile: circles along x
  std::string kids;
  for (int i = 0; i < n; ++i)
    kids += std::string(i ? ", " : "") + R"({"sdf": "sd2Circle", "r": 0.06, "translate": [)" +
            num(0.2f * (static_cast<float>(i) - 0.5f * static_cast<float>(n - 1))) + ", 0.3]}";
  return R"({"op": "opUnion", "children": [)" + kids + "]}";
}

// The pass goes inside the modifiers whose point map stretches nothing, and
// inside a repetition: each cell keeps only the few spheres of the child
// near it (counted in instructions, the fine cells' mean list of render
// -v), and the image and steps are --no-prune's. A twist is kept whole:
// its list is its whole program wherever it is the only shape.
TEST(GraphModifierPruneInside, ModifiersThatStretchNothingArePrunedInside) {
  TempDir dir;
  write_file(dir / "s.toml", kScene);
  const std::string r16 = row(16);
  const std::pair<std::string, std::string> cases[] = {
      {"round", R"("r": 0.02, "children": [)" + r16 + "]"},
      {"shell", R"("thickness": 0.02, "children": [)" + r16 + "]"},
      {"symmetry", R"("axes": [0, 1, 0], "children": [)" + row(16, 0.2f) + "]"},
      {"mirror", R"("n": [0, 1, 0], "w": 0, "children": [)" + row(16, 0.2f) + "]"},
      {"elongate", R"("h": [0, 0.1, 0], "children": [)" + r16 + "]"},
      {"extrude", R"("h": 0.2, "children": [)" + row2(16) + "]"},
      {"revolve", R"("offset": 0.0, "children": [)" + row2(8) + "]"},
      {"repeat", R"("spacing": [0, 0, 1.2], "count": [0, 0, 1], "children": [)" + r16 + "]"},
      {"twist", R"("k": 0.5, "children": [)" + r16 + "]"},
  };
  for (const auto& [op, body] : cases) {
    write_file(dir / "g.json", R"({"root": {"op": ")" + op + R"(", )" + body + "}}");
    std::vector<std::string> args = {"render", (dir / "s.toml").string(), "--size", "48x27", "--aov", "steps",
                                     "--graph-eval", "interpreter", "-v", "-o", (dir / "p.exr").string()};
    const RunResult pruned = run_marchstudio(args);
    ASSERT_EQ(pruned.exit_code, 0) << op << ": " << pruned.err;
    const Image whole = render(dir.path(), "w.exr", {"--graph-eval", "interpreter", "--no-prune"});
    const Image p = read_image(dir / "p.exr");
    EXPECT_LE(max_diff(p, whole), 1.0 / 255 + 1e-6) << op;
    EXPECT_EQ(channel(p, "steps"), channel(whole, "steps")) << op;
    const std::size_t at = pruned.err.find("mean list "), of = pruned.err.find("instructions (of ");
    ASSERT_TRUE(at != std::string::npos && of != std::string::npos) << op << ": " << pruned.err;
    const double mean = std::stod(pruned.err.substr(at + 10)), all = std::stod(pruned.err.substr(of + 17));
    // A repetition's cells between two copies look at both (0.35 of the
    // program here, where the three rows written out as one flat union
    // keep about as many spheres a cell).
    if (op == "twist") EXPECT_EQ(mean, all) << op;
    else EXPECT_LT(mean, (op == "repeat" ? 0.45 : 0.3) * all) << op << ": " << pruned.err;
  }
}

}  // namespace
}  // namespace ms::test
