// A graph file on its own (docs/scene-graph.md#a-graph-file-on-its-own),
// through the real binary: render frames the graph's box wherever it lies
// and however large, with a floor under it; mesh writes the mesh the same
// graph gives through a scene .toml; info prints the graph's summary;
// bench runs it; a .toml with a graph and no [[materials]] meshes and
// renders; JSON that is neither a graph nor Shadertoy's is one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "image_diff.h"
#include "io/image_io.h"
#include "mesh_read.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A box and a ball far from the origin, 100 units across.
const std::string kFar =
    "{\"root\": {\"op\": \"opUnion\", \"translate\": [500, 200, -300], \"children\": [\n"
    "  {\"sdf\": \"sdBox\", \"b\": [40, 20, 30]},\n"
    "  {\"sdf\": \"sdSphere\", \"r\": 25, \"translate\": [40, 30, 0], \"material\": \"ball\"}]}}\n";
// The same shape about a unit across, on the other side.
const std::string kTiny =
    "{\"root\": {\"op\": \"opUnion\", \"translate\": [-3, 0.5, 2], \"scale\": 0.01, \"children\": [\n"
    "  {\"sdf\": \"sdBox\", \"b\": [40, 20, 30]},\n"
    "  {\"sdf\": \"sdSphere\", \"r\": 25, \"translate\": [40, 30, 0], \"material\": \"ball\"}]}}\n";

// The pixels whose primary ray hit the graph (materials 0 and 1: the
// default and "ball"; the floor's is 2): their bounding box, and how many
// hit the floor.
struct Coverage {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1, object = 0, floor = 0;
};

Coverage coverage(const Image& img) {
  const std::vector<float> hit = channel(img, "hit"), mat = channel(img, "material");
  Coverage c;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const size_t i = static_cast<size_t>(y) * img.width + x;
      if (hit.at(i) < 0.5f) continue;
      if (mat.at(i) > 1.5f) {
        ++c.floor;
        continue;
      }
      ++c.object;
      c.x0 = std::min(c.x0, x), c.x1 = std::max(c.x1, x);
      c.y0 = std::min(c.y0, y), c.y1 = std::max(c.y1, y);
    }
  return c;
}

TEST(GraphAlone, RenderFramesTheBoxWhereverItIsAndWhateverItsSize) {
  TempDir dir;
  for (const auto& [name, json] : {std::pair{"far", kFar}, std::pair{"tiny", kTiny}}) {
    write_file(dir / (std::string(name) + ".json"), json);
    const fs::path out = dir / (std::string(name) + ".exr");
    const RunResult r = run_marchstudio({"render", (dir / (std::string(name) + ".json")).string(), "--size", "64x36",
                                         "--aov", "material", "-o", out.string()});
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const Image img = read_image(out);
    ASSERT_EQ(img.width, 64);
    const Coverage c = coverage(img);
    // The whole object in frame, clear of the edges, and around the centre.
    EXPECT_GT(c.object, 64 * 36 / 20) << name;
    EXPECT_GE(c.x0, 2) << name;
    EXPECT_LE(c.x1, 61) << name;
    EXPECT_GE(c.y0, 2) << name;
    EXPECT_LE(c.y1, 33) << name;
    EXPECT_NEAR((c.x0 + c.x1) / 2.0, 31.5, 64 * 0.15) << name;
    EXPECT_NEAR((c.y0 + c.y1) / 2.0, 17.5, 36 * 0.15) << name;
    EXPECT_GT(c.floor, 0) << name << ": no floor under the box";
  }
}

TEST(GraphAlone, MeshIsTheSameGraphsMeshThroughASceneAndWatertight) {
  TempDir dir;
  write_file(dir / "part.json", read_file(source_dir() / "tests" / "data" / "graph" / "part.json"));
  write_file(dir / "part.toml",
             "[scene]\ngraph = \"part.json\"\n[[materials]]\nname = \"ball\"\n[[materials]]\nname = \"floor\"\n");
  const RunResult alone = run_marchstudio({"mesh", "part.json", "-o", "alone.ply", "--resolution", "24"}, dir.path());
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_NE(alone.err.find(" watertight"), std::string::npos) << alone.err;
  EXPECT_EQ(alone.err.find("NOT watertight"), std::string::npos) << alone.err;
  const RunResult scene = run_marchstudio({"mesh", "part.toml", "-o", "scene.ply", "--resolution", "24"}, dir.path());
  ASSERT_EQ(scene.exit_code, 0) << scene.err;
  const ReadMesh a = read_ply(dir / "alone.ply"), b = read_ply(dir / "scene.ply");
  ASSERT_TRUE(a.ok && b.ok);
  ASSERT_GT(a.indices.size(), 0u);
  EXPECT_EQ(a.positions, b.positions);  // the floor is not meshed
  EXPECT_EQ(a.indices, b.indices);
  // Its floor is for images: --planes would mesh nothing more.
  const RunResult planes = run_marchstudio({"mesh", "part.json", "-o", "p.ply", "--resolution", "24", "--planes"},
                                           dir.path());
  EXPECT_EQ(planes.exit_code, 2) << planes.err;
  EXPECT_EQ(count_of(planes.err, "\n"), 1) << planes.err;
  EXPECT_NE(planes.err.find("--planes"), std::string::npos) << planes.err;
  EXPECT_FALSE(fs::exists(dir / "p.ply"));
}

TEST(GraphAlone, InfoPrintsTheGraphsSummaryAndBenchRunsIt) {
  const fs::path part = source_dir() / "tests" / "data" / "graph" / "part.json";
  const RunResult info = run_marchstudio({"info", part.string()});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("scene: part, graph "), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("  graph: 3 primitives, 2 operators"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("(the graph's box)"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("  defaults: camera at "), std::string::npos) << info.out;
  const RunResult bench =
      run_marchstudio({"bench", part.string(), "--size", "16x9", "--frames", "1", "--warmup", "0"});
  ASSERT_EQ(bench.exit_code, 0) << bench.err;
  EXPECT_NE(bench.out.find("primary steps"), std::string::npos) << bench.out;
}

TEST(GraphAlone, ASceneWithAGraphNeedsNoMaterials) {
  TempDir dir;
  write_file(dir / "g.json", "{\"root\": {\"op\": \"opUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 0.5},\n"
                             "  {\"sdf\": \"sdBox\", \"b\": [0.3, 0.3, 0.3], \"translate\": [0.6, 0, 0], "
                             "\"material\": \"steel\"}]}}\n");
  write_file(dir / "g.toml", "[scene]\ngraph = \"g.json\"\n[render]\nwidth = 16\nheight = 16\n");
  const RunResult mesh = run_marchstudio({"mesh", "g.toml", "-o", "g.obj", "--resolution", "16"}, dir.path());
  ASSERT_EQ(mesh.exit_code, 0) << mesh.err;
  EXPECT_NE(read_file(dir / "g.mtl").find("newmtl steel"), std::string::npos) << read_file(dir / "g.mtl");
  const RunResult render = run_marchstudio({"render", "g.toml", "-o", "g.png"}, dir.path());
  ASSERT_EQ(render.exit_code, 0) << render.err;
  EXPECT_TRUE(fs::exists(dir / "g.png"));
}

TEST(GraphAlone, JsonThatIsNeitherAGraphNorShadertoysIsOneLine) {
  TempDir dir;
  write_file(dir / "x.json", "{\"nodes\": [{\"sdf\": \"sdSphere\"}]}\n");
  write_file(dir / "bad.json", "{\"root\": {\"sdf\": \"sdSphere\", \"r\": 1, \"material\": \"my ball\"}}\n");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", "x.json", "-o", "x.png", "--size", "8x8"},
        std::vector<std::string>{"mesh", "x.json", "-o", "x.obj"}, std::vector<std::string>{"info", "x.json"}}) {
    const RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.err;
    EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err;
    EXPECT_NE(r.err.find("marchstudio: x.json:1: neither a scene graph nor Shadertoy JSON ("), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("{\"root\": NODE}"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\"Shader\""), std::string::npos) << r.err;
  }
  // A default material's name must be one GLSL can take: at its pointer.
  const RunResult r = run_marchstudio({"render", "bad.json", "-o", "bad.png", "--size", "8x8"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err;
  EXPECT_NE(r.err.find("bad.json:1: /root/material: material 'my ball'"), std::string::npos) << r.err;
  EXPECT_EQ(dir.entries().size(), 2u);  // nothing written
}

}  // namespace
}  // namespace ms::test
