// One pass at spp 1 (FUSED_POST, render/frame.h): the scene shader writes the
// output image itself. Checked through the real binary: the pixels are the
// ones the two-pass frame (accumulation buffer, then post.frag) makes, for
// linear EXR and for tone-mapped sRGB PNG, and the pass is chosen only where
// it applies (spp 1, no AOVs, an SDF scene).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

std::string scene(const std::string& name) { return (source_dir() / "scenes" / (name + ".toml")).string(); }

Image render(TempDir& dir, const std::string& toml, const std::string& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", toml, "-o", (dir / out).string(), "--size", "96x54"};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(dir / out);
}

int channel(const Image& img, const std::string& name) {
  const auto it = std::find(img.channels.begin(), img.channels.end(), name);
  EXPECT_NE(it, img.channels.end()) << "no channel " << name;
  return it == img.channels.end() ? 0 : static_cast<int>(it - img.channels.begin());
}

// Pixels whose R, G or B differ at all.
size_t differing(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  size_t n = 0;
  for (int y = 0; y < std::min(a.height, b.height); ++y)
    for (int x = 0; x < std::min(a.width, b.width); ++x) {
      bool d = false;
      for (const char* c : {"R", "G", "B"}) d = d || a.at(x, y, channel(a, c)) != b.at(x, y, channel(b, c));
      n += d;
    }
  return n;
}

// The AOV build draws two passes (its colour goes through the float buffer
// and post.frag); without AOVs spp 1 is one pass. The same linear pixels,
// bit for bit: the output transform is the same code (tonemap.glsl).
TEST(FusedPost, LinearExrEqualsTheTwoPassFrame) {
  for (const char* name : {"seed", "stilllife", "columns"}) {
    TempDir dir;
    const Image one = render(dir, scene(name), "one.exr");
    const Image two = render(dir, scene(name), "two.exr", {"--aov", "depth"});
    EXPECT_EQ(differing(one, two), 0u) << name;
  }
}

// The exposure is the fused pass's uniform now: it must still apply.
TEST(FusedPost, ExposureStillApplies) {
  TempDir dir;
  const std::string toml = (dir / "bright.toml").string();
  std::string text = read_file(scene("seed"));
  const size_t at = text.find("exposure = 1.0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 14, "exposure = 2.0");
  write_file(toml, text);
  // Relative includes: the copy's map must resolve next to it.
  write_file(dir / "seed.glsl", read_file(source_dir() / "scenes/seed.glsl"));
  const Image one = render(dir, toml, "one.exr");
  const Image ref = render(dir, scene("seed"), "ref.exr");
  size_t doubled = 0, total = 0;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const float r = ref.at(x, y, 0);
      if (r <= 0.01f) continue;
      ++total;
      doubled += one.at(x, y, 0) == 2.0f * r;  // a doubling is exact in float
    }
  EXPECT_GT(total, 1000u);
  EXPECT_EQ(doubled, total);
}

// 8-bit output: the one-pass PNG holds the two-pass frame's pixels tone
// mapped and encoded: the ACES fit and the sRGB encode applied here, in
// double, to the linear two-pass EXR, agree within one 8-bit step (the GPU's
// pow is not exact in the last bits), and exactly for almost every value.
TEST(FusedPost, PngIsTheToneMappedTwoPassFrame) {
  TempDir dir;
  const Image png = render(dir, scene("seed"), "one.png");
  const Image lin = render(dir, scene("seed"), "two.exr", {"--aov", "depth"});
  auto aces = [](double x) {
    const double v = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    return std::clamp(v, 0.0, 1.0);
  };
  auto srgb = [](double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; };
  size_t off = 0, worst = 0;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < png.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double want = std::round(255.0 * srgb(aces(std::max(0.0, double(lin.at(x, y, c))))));
        const double got = std::round(255.0 * png.at(x, y, c));
        const size_t d = static_cast<size_t>(std::abs(want - got));
        off += d > 0;
        worst = std::max(worst, d);
      }
  EXPECT_LE(worst, 1u);
  EXPECT_LT(off, static_cast<size_t>(png.width * png.height * 3) / 100) << "more than 1% of values off by one";
}

TEST(FusedPost, ChosenOnlyForOneSampleWithoutAovs) {
  auto shader = [](std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", scene("seed"), "--print-shader"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.out;
  };
  EXPECT_NE(shader({}).find("#define FUSED_POST 1"), std::string::npos);
  EXPECT_EQ(shader({"--spp", "2"}).find("#define FUSED_POST 1"), std::string::npos);
  EXPECT_EQ(shader({"--aov", "depth", "-o", "x.exr"}).find("#define FUSED_POST 1"), std::string::npos);
  // The EXR's fused pass keeps linear values; the PNG's encodes them.
  EXPECT_NE(shader({"-o", "x.exr"}).find("#define ENCODE_SRGB 0"), std::string::npos);
  EXPECT_NE(shader({"-o", "x.png"}).find("#define ENCODE_SRGB 1"), std::string::npos);
}

}  // namespace
}  // namespace ms::test
