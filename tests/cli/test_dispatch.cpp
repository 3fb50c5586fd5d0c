// render --dispatch: the scene pass as a compute dispatch gives
// the fragment pass's pixels. Every shipped scene (scenes/*.toml) at 96x54,
// spp 1 (the fused post path) and 4 (accumulation, the post pass), PNG
// within 1/255 and EXR within 1e-5 in every channel, AOV step counts equal;
// the hard cases (scenes/hard/*.toml) in the EXR with AOVs; the NaN guard
// counts the same pixels; bad values are refused. Shadertoy inputs:
// tests/cli/test_dispatch_shadertoy.cpp.
// envlight ([sky] environment) checks that the scene pass's texture inputs
// (the map, sampled with textureLod) are bound for the compute program too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "image_diff.h"
#include "io/image_io.h"
#include "nan_shaders.h"
#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> scenes_in(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml") out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Renders `scene` with `dispatch` into dir/<name>; the image (empty on failure).
Image render(const TempDir& dir, const fs::path& scene, const std::string& dispatch, const std::string& name,
             std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", scene.string(), "--size", "96x54", "--dispatch", dispatch,
                                   "-o",     (dir / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << scene << " " << dispatch << ": " << r.err;
  if (r.exit_code != 0) return {};
  return read_image(dir / name);
}

class DispatchScene : public ::testing::TestWithParam<std::string> {};

TEST_P(DispatchScene, ComputeEqualsFragment) {
  TempDir dir;
  const fs::path scene = source_dir() / "scenes" / (GetParam() + ".toml");
  for (const std::string spp : {"1", "4"}) {
    const Image f = render(dir, scene, "fragment", "f" + spp + ".png", {"--spp", spp});
    const Image c = render(dir, scene, "compute", "c" + spp + ".png", {"--spp", spp});
    EXPECT_LE(max_diff(f, c), 1.0 / 255 + 1e-6) << GetParam() << " spp " << spp << " PNG";
  }
  const Image f = render(dir, scene, "fragment", "f.exr", {"--spp", "4", "--aov", "steps,cost"});
  const Image c = render(dir, scene, "compute", "c.exr", {"--spp", "4", "--aov", "steps,cost"});
  EXPECT_LE(max_diff(f, c), 1e-5) << GetParam() << " EXR";
  for (const std::string ch : {"steps", "shadow_steps", "reflection_steps", "sdf_evals", "step_cap"}) {
    const std::vector<float> a = channel(f, ch), b = channel(c, ch);
    ASSERT_FALSE(a.empty()) << ch;
    EXPECT_EQ(a, b) << GetParam() << ": " << ch << " differs";
  }
  // Not a blank frame on both sides: the scene drew something.
  const std::vector<float> steps = channel(f, "steps");
  EXPECT_GT(*std::max_element(steps.begin(), steps.end()), 0.0f);
}

INSTANTIATE_TEST_SUITE_P(DispatchScenes, DispatchScene, ::testing::ValuesIn(scenes_in(source_dir() / "scenes")),
                         [](const auto& info) { return info.param; });

class DispatchHardCase : public ::testing::TestWithParam<std::string> {};

TEST_P(DispatchHardCase, ComputeEqualsFragment) {
  TempDir dir;
  const fs::path scene = source_dir() / "scenes" / "hard" / (GetParam() + ".toml");
  const Image f = render(dir, scene, "fragment", "f.exr", {"--spp", "4", "--aov", "steps,cost"});
  const Image c = render(dir, scene, "compute", "c.exr", {"--spp", "4", "--aov", "steps,cost"});
  EXPECT_LE(max_diff(f, c), 1e-5) << GetParam();
  EXPECT_EQ(channel(f, "steps"), channel(c, "steps")) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(DispatchHard, DispatchHardCase, ::testing::ValuesIn(scenes_in(source_dir() / "scenes" / "hard")),
                         [](const auto& info) { return info.param; });

// The seed scene with `map` in place of its map(), in `dir`.
fs::path seed_with_map(const TempDir& dir, const std::string& name, const std::string& map) {
  std::string toml = read_file(source_dir() / "scenes/seed.toml");
  toml = std::regex_replace(toml, std::regex(R"(map\s*=\s*"seed.glsl")"), "map  = \"" + name + ".glsl\"");
  write_file(dir / (name + ".toml"), toml);
  write_file(dir / (name + ".glsl"), map);
  return dir / (name + ".toml");
}

// The bloom stage (render/bloom.h) runs between the accumulation and the
// post pass on either dispatch.
TEST(Dispatch, BloomScenesEqualFragment) {
  TempDir dir;
  for (const std::string name : {"orbs", "spot"}) {
    const fs::path scene = source_dir() / "tests/data/bloom" / (name + ".toml");
    for (const std::string spp : {"1", "4"}) {
      const Image f = render(dir, scene, "fragment", name + "f" + spp + ".png", {"--spp", spp});
      const Image c = render(dir, scene, "compute", name + "c" + spp + ".png", {"--spp", spp});
      EXPECT_LE(max_diff(f, c), 1.0 / 255 + 1e-6) << name << " spp " << spp;
    }
  }
}

// A still drawn in tiles (the hidden --tile-still, as past the GL limits):
// each tile a compute dispatch with the whole image's camera, so the bands
// equal the fragment pass's whole image. 32 does not divide 96x54: short
// tiles at the right and top.
TEST(Dispatch, TiledStillsEqualFragment) {
  TempDir dir;
  for (const std::string name : {"seed", "envlight"}) {
    const fs::path scene = source_dir() / "scenes" / (name + ".toml");
    const std::vector<std::string> exr = {"--spp", "4", "--aov", "steps,cost"};
    std::vector<std::string> tiled = exr;
    tiled.insert(tiled.end(), {"--tile-still", "32"});
    const Image whole = render(dir, scene, "fragment", name + "w.exr", exr);
    const Image c = render(dir, scene, "compute", name + "c.exr", tiled);
    EXPECT_LE(max_diff(whole, c), 1e-5) << name;
    EXPECT_EQ(channel(whole, "steps"), channel(c, "steps")) << name;
    const Image fp = render(dir, scene, "fragment", name + "f.png", {"--spp", "1"});
    const Image cp = render(dir, scene, "compute", name + "c.png", {"--spp", "1", "--tile-still", "32"});
    EXPECT_LE(max_diff(fp, cp), 1.0 / 255 + 1e-6) << name << " PNG";
  }
}

// The hidden --compute-group: work group shapes and the striped group order
// (WxH/S, ComputeGroup::stripe) cover every pixel once, partial groups and
// partial stripes included (96x54 is not a multiple of any of them).
TEST(Dispatch, WorkGroupsAndStripesEqualFragment) {
  TempDir dir;
  const fs::path scene = source_dir() / "scenes/seed.toml";
  const std::vector<std::string> exr = {"--spp", "4", "--aov", "steps,cost", "--tile-size", "40"};
  const Image f = render(dir, scene, "fragment", "f.exr", exr);
  for (const std::string g : {"16x8", "32x4", "16x16", "8x8/4", "7x5/3", "32x4/8", "8x8/0"}) {
    std::vector<std::string> args = exr;
    args.insert(args.end(), {"--compute-group", g});
    const Image c = render(dir, scene, "compute", "c.exr", args);
    EXPECT_LE(max_diff(f, c), 1e-5) << g;
    EXPECT_EQ(channel(f, "steps"), channel(c, "steps")) << g;
  }
}

// The NaN guard's flag path (tests/cli/nan_shaders.h: the left 8 columns'
// samples NaN), fused, accumulated and with AOVs.
TEST(Dispatch, NanGuardCountsTheSamePixels) {
  TempDir dir;
  const fs::path shaders = nan_injecting_shader_dir(dir.path());
  ASSERT_FALSE(HasFailure());
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--spp", "1"}, {"--spp", "4"}, {"--spp", "4", "--aov", "depth"}}) {
    for (const std::string d : {"fragment", "compute"}) {
      std::vector<std::string> args = {"render", seed, "--size", "96x54", "--shader-dir", shaders.string(),
                                       "--dispatch", d, "-o", (dir / "x.exr").string()};
      args.insert(args.end(), extra.begin(), extra.end());
      const RunResult r = run_marchstudio(args);
      EXPECT_EQ(r.exit_code, 0) << r.err;
      EXPECT_NE(r.err.find(" 432 of 5184 pixels have NaN/Inf values"), std::string::npos) << d << ": " << r.err;
      args.push_back("--strict");
      args[9] = (dir / "strict.exr").string();  // -o
      const RunResult s = run_marchstudio(args);
      EXPECT_EQ(s.exit_code, 1) << d << ": " << s.err;
      EXPECT_FALSE(fs::exists(dir / "strict.exr")) << d;
    }
  }
}

TEST(Dispatch, BadValueIsOneLineExit2) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "16x16",
                                       "--dispatch", "vertex", "-o", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--dispatch 'vertex'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  const RunResult g = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "16x16",
                                       "--dispatch", "compute", "--compute-group", "64x64", "-o",
                                       (dir / "x.png").string()});
  EXPECT_EQ(g.exit_code, 2) << g.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  for (const std::string bad : {"8x8/", "8x8/x", "8x8-4", "8x8/-1"}) {
    const RunResult b = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "16x16",
                                         "--dispatch", "compute", "--compute-group", bad, "-o",
                                         (dir / "x.png").string()});
    EXPECT_EQ(b.exit_code, 2) << bad << ": " << b.err;
    EXPECT_NE(b.err.find("--compute-group '" + bad + "'"), std::string::npos) << b.err;
  }
}

TEST(Dispatch, SceneWithDerivativesIsRefused) {
  TempDir dir;
  const fs::path scene = seed_with_map(dir, "deriv",
                                       "// fwidth( in a comment is no call\n"
                                       "vec2 map(vec3 p) {\n"
                                       "  return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0 + 0.0 * dFdx(p.x)), MAT_BALL);\n"
                                       "}\n");
  const RunResult r = run_marchstudio(
      {"render", scene.string(), "--size", "16x16", "--dispatch", "compute", "-o", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("calls dFdx()"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("deriv.glsl:3"), std::string::npos) << r.err;  // the call's line
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// No dFdx/dFdy/fwidth call reachable from the scene path: the library and
// every shipped scene, comments aside.
TEST(Dispatch, LibraryAndScenesAreDerivativeFree) {
  const std::regex call(R"(\b(dFdx|dFdy|fwidth)(Fine|Coarse)?\s*\()");
  std::vector<fs::path> files;
  for (const fs::path& d : {source_dir() / "sdf_shaders", source_dir() / "scenes", source_dir() / "scenes/hard"})
    for (const auto& e : fs::directory_iterator(d))
      if (e.path().extension() == ".glsl" || e.path().extension() == ".frag") files.push_back(e.path());
  ASSERT_GT(files.size(), 20u);
  for (const fs::path& f : files) {
    std::string text = read_file(f);
    text = std::regex_replace(text, std::regex(R"(//[^\n]*)"), "");
    EXPECT_FALSE(std::regex_search(text, call)) << f;
  }
}

}  // namespace
}  // namespace ms::test
