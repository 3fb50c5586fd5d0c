// The NaN/Inf guard of render, sequences and bench (docs/stability.md):
// a non-finite sample is zeroed, counted and reported, and --strict fails
// without writing, whichever dispatch draws the scene pass (each test runs
// for both). Split from test_stability.cpp, whose hard cases it guards.
#include <gtest/gtest.h>

#include <regex>

#include <nlohmann/json.hpp>

#include "dispatch.h"
#include "nan_shaders.h"
#include "stability_util.h"

namespace ms::test {
namespace {

using nlohmann::json;

class NanGuard : public BothDispatches {};

// The NaN/Inf guard of render and bench. main.frag and the Shadertoy
// wrapper zero a non-finite sample (it would poison the pixel's sum) but flag
// it, and the post pass turns a flagged pixel NaN, so the guard counts what a
// shader produced, not what survived the clamps.
long long reported_count(const std::string& err) {
  const std::smatch m = [&] {
    std::smatch x;
    std::regex_search(err, x, std::regex("([0-9]+) of [0-9]+ pixels have NaN/Inf values"));
    return x;
  }();
  return m.empty() ? -1 : std::stoll(m[1]);
}

TEST_P(NanGuard, RenderCountsNonFinitePixelsAndStrictFailsWithoutWriting) {
  TempDir dir;
  const std::string nan = (source_dir() / "tests/data/stability/nan_shadertoy.glsl").string();
  const RunResult warn =
      run_marchstudio(with_dispatch({"render", nan, "--size", "32x18", "-o", (dir / "w.exr").string()}));
  EXPECT_EQ(warn.exit_code, 0) << warn.err;
  EXPECT_EQ(reported_count(warn.err), 8 * 18) << warn.err;  // the shader's 8 NaN columns
  EXPECT_TRUE(fs::exists(dir / "w.exr"));
  const RunResult strict =
      run_marchstudio(with_dispatch({"render", nan, "--size", "32x18", "--spp", "4", "-o", (dir / "s.png").string(),
                                     "--strict"}));
  EXPECT_EQ(strict.exit_code, 1) << strict.err;
  EXPECT_EQ(reported_count(strict.err), 8 * 18) << strict.err;  // one bad sample of 4 is enough
  EXPECT_EQ(std::count(strict.err.begin(), strict.err.end(), '\n'), 1) << strict.err;
  EXPECT_FALSE(fs::exists(dir / "s.png"));
}

TEST_P(NanGuard, ANonFiniteSceneSampleIsCountedWithAndWithoutAovs) {
  TempDir dir;
  const fs::path shaders = nan_injecting_shader_dir(dir.path());
  const std::string scene = hard_scene("degenerate").string();
  for (const std::vector<std::string>& extra : {std::vector<std::string>{}, {"--aov", "depth"}}) {
    std::vector<std::string> args = {"render", scene,          "--size", "32x18", "--shader-dir",
                                     shaders.string(), "-o", (dir / "m.exr").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(with_dispatch(args));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(reported_count(r.err), 8 * 18) << r.err;
    args.push_back("--strict");
    fs::remove(dir / "m.exr");
    const RunResult s = run_marchstudio(with_dispatch(args));
    EXPECT_EQ(s.exit_code, 1) << s.err;
    EXPECT_FALSE(fs::exists(dir / "m.exr"));
  }
  // The shipped library: nothing to report, --strict passes, stderr stays quiet.
  const RunResult ok =
      run_marchstudio(with_dispatch({"render", scene, "--size", "32x18", "-o", (dir / "ok.png").string(), "--strict"}));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.err, "");
}

// A map() that returns NaN over half the scene: the tracer takes a NaN
// distance for "no surface here" (every comparison with NaN is false), so
// those rays show sky and no pixel is non-finite.
TEST_P(NanGuard, ANanFieldReadsAsEmptySpace) {
  TempDir dir;
  const std::string scene = (source_dir() / "tests/data/stability/nan_map.toml").string();
  const RunResult r = run_marchstudio(with_dispatch(
      {"render", scene, "--size", "32x18", "--aov", "hit", "-o", (dir / "m.exr").string(), "--strict"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "m.exr");
  const int hit = static_cast<int>(std::find(img.channels.begin(), img.channels.end(), "hit") - img.channels.begin());
  // The camera looks down +z with up +y, so the image's right is world -x:
  // the field's finite half (x < 0) is the image's right half.
  int nan_half = 0, finite_half = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) (x < img.width / 2 ? nan_half : finite_half) += img.at(x, y, hit) > 0.5f;
  EXPECT_GT(finite_half, 0);
  EXPECT_EQ(nan_half, 0);
}

// A sequence checks every frame: a warning per bad frame without --strict;
// with it the run stops at the first one, which is not written.
TEST_P(NanGuard, SequencesCheckEveryFrame) {
  TempDir dir;
  const std::string nan = (source_dir() / "tests/data/stability/nan_shadertoy.glsl").string();
  const RunResult warn = run_marchstudio(with_dispatch(
      {"render", nan, "--frames", "0..2", "--size", "32x18", "-o", (dir / "w_%d.png").string()}));
  EXPECT_EQ(warn.exit_code, 0) << warn.err;
  // The shader's NaN is 0/0 with iTime = 0: frame 0 only.
  EXPECT_NE(warn.err.find("frame 0: 144 of 576 pixels have NaN/Inf values"), std::string::npos) << warn.err;
  EXPECT_EQ(warn.err.find("frame 1: "), std::string::npos) << warn.err;
  EXPECT_EQ(warn.err.find("frame 2: "), std::string::npos) << warn.err;
  for (int f = 0; f < 3; ++f) EXPECT_TRUE(fs::exists(dir / ("w_" + std::to_string(f) + ".png")));
  const RunResult strict = run_marchstudio(with_dispatch(
      {"render", nan, "--frames", "0..2", "--size", "32x18", "-o", (dir / "s_%d.png").string(), "--strict"}));
  EXPECT_EQ(strict.exit_code, 1) << strict.err;
  EXPECT_NE(strict.err.find("frame 0: 144 of 576 pixels have NaN/Inf values; it is not written"), std::string::npos)
      << strict.err;
  for (int f = 0; f < 3; ++f) EXPECT_FALSE(fs::exists(dir / ("s_" + std::to_string(f) + ".png")));
}

TEST_P(NanGuard, BenchReportsTheCountInJson) {
  const auto count = [this](const std::string& scene, bool strict) {
    std::vector<std::string> args = {"bench", scene, "--size", "32x18", "--frames", "1", "--warmup", "0", "--json"};
    if (strict) args.push_back("--strict");
    return run_marchstudio(with_dispatch(args));
  };
  const RunResult clean = count(hard_scene("degenerate").string(), true);
  EXPECT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(json::parse(clean.out).at("cost").at("nonfinite_pixels").get<long long>(), 0);
  TempDir dir;
  const fs::path shaders = nan_injecting_shader_dir(dir.path());
  for (const bool strict : {false, true}) {
    std::vector<std::string> args = {"bench", hard_scene("degenerate").string(), "--size", "32x18", "--frames", "1",
                                     "--warmup", "0", "--json", "--shader-dir", shaders.string()};
    if (strict) args.push_back("--strict");
    const RunResult bad = run_marchstudio(with_dispatch(args));
    if (strict) {
      EXPECT_EQ(bad.exit_code, 1) << bad.err;
    } else {
      EXPECT_EQ(bad.exit_code, 0) << bad.err;
      EXPECT_EQ(json::parse(bad.out).at("cost").at("nonfinite_pixels").get<long long>(), 8 * 18) << bad.out;
    }
  }
}

INSTANTIATE_BOTH_DISPATCHES(NanGuard);

}  // namespace
}  // namespace ms::test
