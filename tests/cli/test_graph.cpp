// Graph scenes through the real binary (docs/scene-graph.md): the graph
// renders the image of the same scene written as map() on both dispatches,
// `info` describes it, a declared [bounds] that cuts its box warns (and
// fails under --strict), and a broken graph is one line naming its place.
#include <gtest/gtest.h>

#include <string>

#include "dispatch.h"
#include "image_diff.h"
#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

const std::filesystem::path kData = source_dir() / "tests/data/graph";

class GraphRender : public BothDispatches {};

// Pixels differing by more than 1/255 in any channel.
int differing(const Image& a, const Image& b) {
  const size_t nc = a.channels.size();
  int n = 0;
  for (size_t i = 0; i + nc <= a.pixels.size() && a.pixels.size() == b.pixels.size(); i += nc) {
    bool d = false;
    for (size_t c = 0; c < nc; ++c) d = d || std::fabs(a.pixels[i + c] - b.pixels[i + c]) > 1.0 / 255 + 1e-6;
    n += d;
  }
  return a.pixels.size() == b.pixels.size() ? n : 1 << 30;
}

// part.toml written to `file` with a [bounds] box of its own, part.json
// beside it (a graph file is read only from the scene's folder).
void part_with_bounds(const std::filesystem::path& file, const std::string& min, const std::string& max) {
  std::string toml = read_file(kData / "part.toml");
  toml.replace(toml.find("graph = \"part.json\"\n"), 20,
               "graph = \"part.json\"\n\n[bounds]\nmin = " + min + "\nmax = " + max + "\n");
  write_file(file, toml);
  write_file(file.parent_path() / "part.json", read_file(kData / "part.json"));
}

TEST_P(GraphRender, TheGraphGivesTheImageOfTheSameMapWrittenByHand) {
  TempDir dir;
  // The graph with the map scene's own [bounds]: the same rays, the same image.
  part_with_bounds(dir / "same_bounds.toml", "[-1.35, -0.2, -1.0]", "[1.35, 1.5, 1.0]");
  for (const auto& [scene, out] : std::vector<std::pair<std::string, std::string>>{
           {(kData / "part_map.toml").string(), "map.png"},
           {(dir / "same_bounds.toml").string(), "graph.png"},
           {(kData / "part.toml").string(), "auto.png"}}) {
    const RunResult r = run_marchstudio(with_dispatch({"render", scene, "--size", "160x90", "-o", (dir / out).string()}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
  }
  const Image map = read_image(dir / "map.png"), graph = read_image(dir / "graph.png");
  EXPECT_LE(max_diff(map, graph), 1.0 / 255 + 1e-6);
  // Its own, tighter box starts the rays elsewhere: a few silhouette pixels
  // may land a tolerance apart.
  EXPECT_LE(differing(map, read_image(dir / "auto.png")), 160 * 90 / 500);
}

INSTANTIATE_BOTH_DISPATCHES(GraphRender);

TEST(GraphInfo, PrintsTheCountsTheBoxAndTheBound) {
  const RunResult r = run_marchstudio({"info", (kData / "part.toml").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("graph: 3 primitives, 2 operators (2 binary, 0 modifiers), box ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Lipschitz bound 1.41421"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(the graph's box)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lipschitz: 1.41421 (the graph's bound)"), std::string::npos) << r.out;
}

TEST(GraphBounds, ADeclaredBoundsCuttingTheBoxWarnsAndStrictFailsWithoutAFile) {
  TempDir dir;
  part_with_bounds(dir / "cut.toml", "[-1, -1, -1]", "[1, 1, 1]");
  const RunResult warn = run_marchstudio({"render", (dir / "cut.toml").string(), "--size", "32x18", "-o", (dir / "a.png").string()});
  EXPECT_EQ(warn.exit_code, 0) << warn.err;
  EXPECT_NE(warn.err.find("the scene graph's box pokes out of [bounds] by"), std::string::npos) << warn.err;
  EXPECT_NE(warn.err.find("along +y"), std::string::npos) << warn.err;
  const RunResult strict = run_marchstudio(
      {"render", (dir / "cut.toml").string(), "--size", "32x18", "--strict", "-o", (dir / "b.png").string()});
  EXPECT_EQ(strict.exit_code, 1) << strict.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.png"));
}

TEST(GraphErrors, ABrokenGraphIsOneLineWithFileLineAndPointerAndNoOutput) {
  TempDir dir;
  write_file(dir / "g.json", "{\"root\": {\"op\": \"opUnion\", \"children\": [\n {\"sdf\": \"sdSphere\", \"r\": 1},\n"
                             " {\"sdf\": \"sdBox\", \"b\": [1, \"x\", 1]}]}}\n");
  write_file(dir / "s.toml", "[scene]\ngraph = \"g.json\"\n[[materials]]\nname = \"m\"\n");
  const RunResult r = run_marchstudio({"render", (dir / "s.toml").string(), "--size", "32x18", "-o", (dir / "o.png").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "marchstudio: " + (dir / "g.json").string() + ":3: /root/children/1/b/1: each element of 'b' must be a number\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "o.png"));
}

}  // namespace
}  // namespace ms::test
