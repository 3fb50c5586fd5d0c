// A new pose of an animated graph prunes again only where a moved node may
// change the field (shader/graph_repose.h, docs/scene-graph.md#animation):
// moving one sphere of a 600-sphere cloud re-prunes under a tenth of the
// cells (counted, as render -v prints them), and every frame of the
// sequence, whose lists are the earlier frames' where nothing moved, is
// the image and step counts of a still at its time, whose grid is pruned
// whole.
#include <gtest/gtest.h>

#include <cstdint>
#include <regex>
#include <string>

#include "image_diff.h"
#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

// 600 small spheres scattered through a cube (a fixed sequence) under a
// plain union, the first named "mover"; [bounds] fixed, so the grid
// stays where it is.
std::string cloud_json() {
  std::string kids;
  std::uint32_t seed = 12345;
  const auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return -1.4 + 2.8 * static_cast<double>(seed >> 8) / 16777216.0;
  };
  for (int i = 0; i < 600; ++i) {
    const double x = next(), y = next() + 1.5, z = next();
    kids += std::string(i ? ",\n" : "") + "{\"sdf\": \"sdSphere\", \"r\": 0.05" + (i ? "" : ", \"name\": \"mover\"") +
            ", \"translate\": [" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "]}";
  }
  return "{\"root\": {\"op\": \"opUnion\", \"children\": [\n" + kids + "\n]}}\n";
}

// The mover steps a little (frames 0 to 2 at 2 fps), then jumps across
// the cloud (frame 3).
const char* kScene =
    "[scene]\nname = \"cloud\"\ngraph = \"cloud.json\"\n\n"
    "[camera]\nposition = [-3.0, 3.5, -4.5]\ntarget = [0.0, 1.5, 0.0]\nfov = 50.0\n\n"
    "[bounds]\nmin = [-1.5, 0.05, -1.5]\nmax = [1.5, 2.95, 1.5]\n\n"
    "[[planes]]\nnormal = [0.0, 1.0, 0.0]\noffset = 0.0\nmaterial = \"floor\"\n\n"
    "[[materials]]\nname = \"floor\"\ncolor = [0.6, 0.6, 0.6]\n\n"
    "[[lights]]\ntype = \"point\"\nposition = [1.0, 4.0, -2.0]\nintensity = 2.0\nsize = 0.3\n\n"
    "[[animation]]\ntarget = \"graph.mover.translate\"\n"
    "keys = [[0.0, -1.0, 1.5, -1.0], [1.0, -0.9, 1.5, -1.0], [1.5, 0.5, 2.5, 0.5]]\n";

TEST(GraphRepose, OneMovedNodePrunesOnlyNearItAndEveryFrameIsTheStillAtItsTime) {
  const TempDir dir;
  write_file(dir / "cloud.json", cloud_json());
  write_file(dir / "cloud.toml", kScene);
  const RunResult seq = run_marchstudio({"render", "cloud.toml", "--frames", "0..3", "--fps", "2", "--size", "64x36",
                                         "--aov", "steps", "-v", "-o", "f_%d.exr"},
                                        dir.path());
  ASSERT_EQ(seq.exit_code, 0) << seq.err;
  const std::regex line(R"(frame (\d): graph posed, 0 programs compiled, pruning [0-9.]+ ms \((\d+) of (\d+) cells\))");
  int posed = 0;
  for (std::sregex_iterator it(seq.err.begin(), seq.err.end(), line), end; it != end; ++it, ++posed) {
    const int frame = std::stoi((*it)[1]), cells = std::stoi((*it)[2]), all = std::stoi((*it)[3]);
    // The small steps prune again only near the mover (frame 3's jump
    // across the cloud is checked for its image only).
    EXPECT_GT(all, 100);
    if (frame == 1 || frame == 2) EXPECT_GT(cells, 0) << (*it)[0];
    if (frame == 1 || frame == 2) EXPECT_LE(10 * cells, all) << (*it)[0];
  }
  EXPECT_EQ(posed, 4) << seq.err;
  for (int f = 1; f <= 3; ++f) {
    const std::string t = std::to_string(0.5 * f), still = "s_" + std::to_string(f) + ".exr";
    const RunResult r = run_marchstudio({"render", "cloud.toml", "--time", t, "--fps", "2", "--size", "64x36", "--aov",
                                         "steps", "-o", still},
                                        dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image a = read_image(dir / ("f_" + std::to_string(f) + ".exr")), b = read_image(dir / still);
    EXPECT_EQ(max_diff(a, b), 0.0) << "frame " << f;
    EXPECT_EQ(channel(a, "steps"), channel(b, "steps")) << "frame " << f;
  }
}

}  // namespace
}  // namespace ms::test
