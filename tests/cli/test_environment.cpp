// HDR environment maps through the real binary: the map is
// what escaping rays see (its texels, turned by rotation, times intensity,
// in a linear EXR), its irradiance is the ambient light (AO still applies),
// the irradiance is cached by the file's content hash and read back from
// there, a scene without a map carries none of its code, and bad keys are
// one-line errors. The test writes its own maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A 64x32 map: red 1 where the direction points up, green 1 towards +x
// (u in (0.5, 1)), blue 0.25 everywhere.
void write_map(const fs::path& p) {
  Image m;
  m.width = 64;
  m.height = 32;
  m.channels = {"R", "G", "B"};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) m.pixels.insert(m.pixels.end(), {y < 16 ? 1.0f : 0.0f, x >= 32 ? 1.0f : 0.0f, 0.25f});
  write_image(m, p);
}

// A far-away ball (misses everywhere near the edges), the camera at the
// origin looking along +z with a 90 degree field of view.
std::string scene(const std::string& sky) {
  return "[scene]\nname = \"env\"\nmap = \"m.glsl\"\n"
         "[camera]\nposition = [0.0, 0.0, 0.0]\ntarget = [0.0, 0.0, 1.0]\nup = [0.0, 1.0, 0.0]\nfov = 90.0\n"
         "[render]\nwidth = 64\nheight = 64\nexposure = 1.0\n"
         "[sky]\n" + sky +
         "[[lights]]\ntype = \"directional\"\ndirection = [0.0, -1.0, 0.0]\nintensity = 0.0\n"
         "[[materials]]\nname = \"ball\"\ncolor = [1.0, 1.0, 1.0]\n";
}
const char* kMap = "vec2 map(vec3 p) { return vec2(sdSphere(p - vec3(0.0, 0.0, 6.0), 1.0), MAT_BALL); }\n";

struct Dir {
  TempDir dir;
  Dir() {
    write_map(dir / "sky.exr");
    write_file(dir / "m.glsl", kMap);
  }
  Image render(const std::string& sky, const std::vector<std::string>& extra = {}) {
    write_file(dir / "s.toml", scene(sky));
    std::vector<std::string> args = {"render", "s.toml", "-o", "o.exr"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args, dir.path(), "XDG_CACHE_HOME='" + (dir / "cache").string() + "' ");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? read_image(dir / "o.exr") : Image{};
  }
};

TEST(Environment, EscapingRaysSeeTheMapTurnedAndScaled) {
  Dir d;
  const Image a = d.render("environment = \"sky.exr\"\n");
  ASSERT_EQ(a.width, 64);
  // The image's right is -x (right = forward x up): its upper left looks up
  // and towards +x, its lower right down and towards -x.
  EXPECT_NEAR(a.at(4, 4, 0), 1.0f, 1e-4f);
  EXPECT_NEAR(a.at(4, 4, 1), 1.0f, 1e-4f);
  EXPECT_NEAR(a.at(4, 4, 2), 0.25f, 1e-4f);
  EXPECT_NEAR(a.at(59, 59, 0), 0.0f, 1e-4f);
  EXPECT_NEAR(a.at(59, 59, 1), 0.0f, 1e-4f);
  // Turned half a turn about +y, x swaps sides; intensity scales it all.
  const Image b = d.render("environment = \"sky.exr\"\nrotation = 180.0\nintensity = 0.5\n");
  EXPECT_NEAR(b.at(4, 4, 1), 0.0f, 1e-4f);
  EXPECT_NEAR(b.at(59, 59, 1), 0.5f, 1e-4f);
  EXPECT_NEAR(b.at(4, 4, 0), 0.5f, 1e-4f);
  EXPECT_NEAR(b.at(4, 4, 2), 0.125f, 1e-4f);
}

TEST(Environment, IrradianceLightsTheBallAndIsCachedByContent) {
  Dir d;
  const Image lit = d.render("environment = \"sky.exr\"\n");
  // The ball (rows 27..37 around the centre): its top faces the red upper
  // half, its underside none of it.
  const float top = lit.at(32, 29, 0), bottom = lit.at(32, 35, 0);
  EXPECT_GT(top, bottom + 0.05f) << "the ambient light does not follow the map";
  EXPECT_LT(bottom, 0.5f * top);
  EXPECT_GT(lit.at(32, 32, 2), 0.01f);
  // AO still darkens the ambient term.
  const Image no_ao = d.render("environment = \"sky.exr\"\n", {"--disable", "ao"});
  double diff = 0;
  for (size_t i = 0; i < lit.pixels.size(); ++i) diff += std::abs(lit.pixels[i] - no_ao.pixels[i]);
  EXPECT_GT(diff, 0.01) << "--disable ao changed nothing under an environment map";
  // The coefficients were written under the cache; replaced by a tenth of
  // themselves (plausible: zeros or 1e38 would be computed again,
  // EnvironmentCache.*), the next render reads them back: little ambient
  // light, the sky unchanged.
  std::vector<fs::path> cached;
  for (const auto& e : fs::recursive_directory_iterator(d.dir / "cache" / "marchstudio"))
    if (e.is_regular_file()) cached.push_back(e.path());
  ASSERT_EQ(cached.size(), 1u);
  EXPECT_EQ(cached[0].parent_path().filename(), "irradiance");
  {
    std::vector<float> c;
    std::ifstream in(cached[0]);
    for (float x; in >> x;) c.push_back(x * 0.1f);
    ASSERT_EQ(c.size(), 27u);
    std::ofstream dim(cached[0]);
    for (size_t i = 0; i < c.size(); i += 3) dim << c[i] << ' ' << c[i + 1] << ' ' << c[i + 2] << '\n';
  }
  const Image dark = d.render("environment = \"sky.exr\"\n");
  EXPECT_LT(dark.at(32, 29, 0), top * 0.5f) << "the cached coefficients were not used";
  EXPECT_NEAR(dark.at(4, 4, 0), 1.0f, 1e-4f);
}

TEST(Environment, WithoutAMapTheShaderHasNoneOfItsCode) {
  Dir d;
  write_file(d.dir / "s.toml", scene("horizon = [0.5, 0.5, 0.5]\n"));
  RunResult r = run_marchstudio({"render", "s.toml", "--print-shader"}, d.dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // ENV_MAP stays 0: the preprocessor drops every line of it before the driver compiles.
  EXPECT_EQ(r.out.find("#define ENV_MAP 1"), std::string::npos);
  write_file(d.dir / "s.toml", scene("environment = \"sky.exr\"\n"));
  r = run_marchstudio({"render", "s.toml", "--print-shader"}, d.dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("#define ENV_MAP 1"), std::string::npos);
}

TEST(Environment, BadKeysAreOneLineErrors) {
  Dir d;
  write_file(d.dir / "flat.png", "");
  const struct {
    std::string sky, says;
  } cases[] = {{"environment = \"gone.exr\"\n", "s.toml:14: sky.environment: environment file 'gone.exr' not found"},
               {"environment = \"flat.png\"\n", "is not an .exr or .hdr file"},
               {"rotation = 10.0\n", "sky.rotation has no effect without sky.environment"},
               {"environment = \"sky.exr\"\nintensity = -1.0\n", "sky.intensity"}};
  for (const auto& c : cases) {
    write_file(d.dir / "s.toml", scene(c.sky));
    const RunResult r = run_marchstudio({"render", "s.toml", "-o", "x.png"}, d.dir.path());
    EXPECT_EQ(r.exit_code, 2) << c.sky << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(d.dir / "x.png"));
  }
}

}  // namespace
}  // namespace ms::test
