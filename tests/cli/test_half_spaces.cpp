// Half-spaces in a graph scene: boxes and spheres cut by sdSlab and sdPlane
// (inside an intersection, as what a subtraction removes) render pruned as
// they do unpruned, on both dispatches, mesh watertight, and an unbounded
// graph is refused at the node that makes it so, with nothing written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "dispatch.h"
#include "image_diff.h"
#include "io/image_io.h"
#include "graph_scene.h"
#include "run.h"

namespace ms::test {
namespace {

// A sphere with a flat top (a slab open above, below y = 0.2), a box with a
// slot through it (minus a slab open along y and z), a box with a corner
// cut off (minus a tilted plane) and a ball under a plane, with a
// one-sided slab (x >= -1.4) over the lot.
const char* kGraph = R"({"root": {"op": "opIntersection", "children": [
  {"op": "opUnion", "children": [
    {"op": "opIntersection", "children": [
      {"sdf": "sdSphere", "r": 0.5},
      {"sdf": "sdSlab", "y": [null, 0.2]}]},
    {"op": "opSubtraction", "translate": [1.1, 0, 0], "material": "b", "children": [
      {"sdf": "sdBox", "b": [0.4, 0.4, 0.4]},
      {"sdf": "sdSlab", "x": [-0.08, 0.08]}]},
    {"op": "opSubtraction", "translate": [-1.1, 0, 0], "children": [
      {"sdf": "sdBox", "b": [0.4, 0.4, 0.4]},
      {"sdf": "sdPlane", "n": [0.6, 0.8, 0], "w": -0.2}]},
    {"op": "opSmoothIntersection", "k": 0.05, "translate": [0, 0, 1.1], "material": "b", "children": [
      {"sdf": "sdSphere", "r": 0.4},
      {"sdf": "sdPlane", "n": [0, 0.8, 0.6], "w": -0.1}]}]},
  {"sdf": "sdSlab", "x": [-1.4, null]}]}}
)";

const std::string kScene = graph_test_scene("[1.8, 1.6, -2.8]", "[0.0, 0.0, 0.3]", 50.0, 0.6);

class HalfSpaces : public BothDispatches {
 protected:
  void SetUp() override {
    write_file(dir_ / "g.json", kGraph);
    write_file(dir_ / "s.toml", kScene);
  }
  Image render(const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", (dir_ / "s.toml").string(), "--size", "64x36", "--graph-eval",
                                     "interpreter", "-o", (dir_ / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(with_dispatch(args));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_image(dir_ / name);
  }
  TempDir dir_;
};

TEST_P(HalfSpaces, PrunedRendersAsTheWholeGraph) {
  const Image pruned = render("p.exr", {});
  const Image whole = render("w.exr", {"--no-prune"});
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float> a = channel(pruned, c), b = channel(whole, c);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    double m = 0.0, lit = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      m = std::max(m, static_cast<double>(std::fabs(a[i] - b[i])));
      lit = std::max(lit, static_cast<double>(a[i]));
    }
    EXPECT_LE(m, 1.0 / 255 + 1e-6) << "channel " << c;
    EXPECT_GT(lit, 0.05) << "channel " << c << ": the scene rendered black";
  }
}

INSTANTIATE_BOTH_DISPATCHES(HalfSpaces);

// Primitives evaluated a pixel, on the mean (bench's counting pass).
double primitive_evals(const std::filesystem::path& scene, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"bench", scene.string(), "--size", "64x36", "--graph-eval", "interpreter",
                                   "--frames", "1", "--warmup", "0", "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out)["cost"]["primitive_evals"]["mean"].get<double>();
}

TEST(HalfSpacesCost, TheGridKeepsTheHalfSpacesOnlyWhereTheyMatter) {
  TempDir dir;
  write_file(dir / "g.json", kGraph);
  write_file(dir / "s.toml", kScene);
  // 74 a pixel unpruned, 16 pruned, when this was written.
  const double all = primitive_evals(dir / "s.toml", {"--no-prune"}), kept = primitive_evals(dir / "s.toml", {});
  EXPECT_GT(all, 0.0);
  EXPECT_LT(kept, 0.5 * all);
}

TEST(HalfSpacesMesh, TheCutShapesMeshWatertight) {
  TempDir dir;
  write_file(dir / "g.json", kGraph);
  write_file(dir / "s.toml", kScene);
  for (const char* eval : {"inline", "interpreter"}) {
    const RunResult r = run_marchstudio({"mesh", (dir / "s.toml").string(), "-o", (dir / "cut.ply").string(),
                                         "--resolution", "64", "--graph-eval", eval, "--json"},
                                        dir.path());
    ASSERT_EQ(r.exit_code, 0) << eval << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["manifold"].get<bool>()) << eval << ": " << j["check"]["summary"];
  }
}

TEST(HalfSpacesErrors, AnUnboundedGraphNamesItsNodeAndWritesNothing) {
  TempDir dir;
  write_file(dir / "g.json",
             "{\"root\": {\"op\": \"opUnion\", \"children\": [\n  {\"sdf\": \"sdSphere\", \"r\": 0.5},\n"
             "  {\"sdf\": \"sdSlab\", \"y\": [0, 0.1]}]}}\n");
  write_file(dir / "s.toml", kScene);
  for (const char* cmd : {"render", "mesh"}) {
    const std::string out = (dir / (std::string(cmd) + (cmd[0] == 'r' ? ".png" : ".ply"))).string();
    const RunResult r = run_marchstudio({cmd, (dir / "s.toml").string(), "-o", out}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("g.json:3: /root/children/1: the graph is unbounded: an infinite sdSlab not cut by an "
                         "intersection"),
              std::string::npos)
        << cmd << ": " << r.err;
    EXPECT_EQ(count_files(dir.path(), cmd), 0) << cmd;
  }
}

}  // namespace
}  // namespace ms::test
