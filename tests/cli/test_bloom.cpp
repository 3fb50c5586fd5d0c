// [post.bloom] (docs/post.md) through the real binary, on tests/data/bloom/:
// a small sphere of linear radiance ~20 in the middle of a sky of 0.02.
// Bloom brightens the pixels around it symmetrically and leaves those far
// away alone; a threshold above the image, --disable bloom and an .exr
// without `exr = true` give exactly the pixels of no bloom; bad values are
// one line naming file:line and the key, exit 2, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <memory>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {

const std::filesystem::path kData = source_dir() / "tests" / "data" / "bloom";

// spot.toml without its [post.bloom] table, plus `bloom` (a table body) when given.
std::string scene_text(const std::string& bloom) {
  std::string text = read_file(kData / "spot_plain.toml");
  if (!bloom.empty()) text += "\n[post.bloom]\n" + bloom;
  return text;
}

struct Bloom : ::testing::Test {
  TempDir dir;
  void SetUp() override { write_file(dir / "spot.glsl", read_file(kData / "spot.glsl")); }

  std::filesystem::path scene(const std::string& name, const std::string& bloom) {
    write_file(dir / name, scene_text(bloom));
    return dir / name;
  }
  Image render(const std::filesystem::path& toml, const std::string& out, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"render", toml.string(), "-o", (dir / out).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? read_image(dir / out) : Image{};
  }
};

// Largest |a - b| over R, G, B of every pixel.
float max_diff(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.width != b.width || a.height != b.height || a.width == 0) return INFINITY;
  float m = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(a.at(x, y, c) - b.at(x, y, c)));
  return m;
}

const char* kSpot = "threshold = 1.0\nintensity = 0.5\nradius = 4.0\nscale = 0.25\npasses = 2\n";

// PNG: pixels 4..8 px from the spot's edge (its radius is ~2.3 px at 96x64)
// gain at least 8/255 in green; pixels 30 px or more from the centre
// (beyond the blur's reach: 3 sigma per pass, plus the box and bilinear
// footprints) keep their value within 1/255.
TEST_F(Bloom, BrightensNearTheSpotOnly) {
  const Image plain = render(kData / "spot_plain.toml", "plain.png");
  const Image bloom = render(kData / "spot.toml", "bloom.png");
  ASSERT_EQ(plain.width, 96);
  ASSERT_EQ(bloom.width, 96);
  int near = 0, far = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 96; ++x) {
      const double r = std::hypot(x + 0.5 - 48.0, y + 0.5 - 32.0);
      const float gain = bloom.at(x, y, 1) - plain.at(x, y, 1);
      if (r >= 6.5 && r <= 10.5) {
        ++near;
        EXPECT_GE(gain, 8.0f / 255) << "at " << x << "," << y << " (r " << r << ")";
      }
      if (r >= 30.0) {
        ++far;
        EXPECT_LE(std::abs(gain), 1.0f / 255 + 1e-6f) << "at " << x << "," << y;
      }
    }
  EXPECT_GT(near, 100);
  EXPECT_GT(far, 2000);
}

// Linear EXR with exr = true: what bloom adds (bloom - plain) is the same
// at (48 + d, y) and (47 - d, y), and at (x, 32 + d) and (x, 31 - d),
// within 1% of the larger value plus 1e-5 (the sphere itself is traced with
// float noise; the blur's weights are symmetric and the 24x16 target
// divides the image exactly). And it is radially decreasing on the axes.
TEST_F(Bloom, SymmetricAroundTheSpot) {
  const Image plain = render(kData / "spot_plain.toml", "plain.exr");
  const Image bloom = render(scene("exr.toml", std::string(kSpot) + "exr = true\n"), "bloom.exr");
  ASSERT_EQ(bloom.width, 96);
  const auto added = [&](int x, int y) { return bloom.at(x, y, 1) - plain.at(x, y, 1); };
  float prev = INFINITY;
  for (int d = 3; d < 24; ++d) {
    const float right = added(48 + d, 31), left = added(47 - d, 31);
    const float up = added(47, 32 + d), down = added(47, 31 - d);
    EXPECT_NEAR(right, left, 0.01f * std::max(right, left) + 1e-5f) << "d " << d;
    EXPECT_NEAR(up, down, 0.01f * std::max(up, down) + 1e-5f) << "d " << d;
    EXPECT_LE(right, prev + 1e-6f) << "d " << d;
    prev = right;
  }
  EXPECT_GT(added(48 + 5, 31), 0.05f);  // it did add light
}

// A threshold above the image's brightest pixel (~20) adds exactly zero.
TEST_F(Bloom, ThresholdAboveTheImageChangesNothing) {
  const Image plain = render(kData / "spot_plain.toml", "plain.png");
  const Image high = render(scene("high.toml", "threshold = 1000.0\nintensity = 3.0\n"), "high.png");
  EXPECT_EQ(max_diff(plain, high), 0.0f);
  EXPECT_EQ(plain.pixels, high.pixels);
}

TEST_F(Bloom, DisableBloomEqualsNoTable) {
  const Image plain = render(kData / "spot_plain.toml", "plain.png");
  const Image off = render(kData / "spot.toml", "off.png", {"--disable", "bloom"});
  const Image on = render(kData / "spot.toml", "on.png");
  EXPECT_EQ(plain.pixels, off.pixels);
  EXPECT_GT(max_diff(plain, on), 0.1f);  // and bloom is there without the flag
  // More samples (the accumulation path without fusing) agree as well.
  const Image plain4 = render(kData / "spot_plain.toml", "plain4.png", {"--spp", "4"});
  const Image off4 = render(kData / "spot.toml", "off4.png", {"--spp", "4", "--disable", "bloom"});
  EXPECT_EQ(plain4.pixels, off4.pixels);
}

// An .exr keeps the pre-bloom linear image unless [post.bloom] exr = true.
TEST_F(Bloom, ExrIsThePreBloomImage) {
  const Image plain = render(kData / "spot_plain.toml", "plain.exr");
  const Image bloom = render(kData / "spot.toml", "bloom.exr");
  EXPECT_EQ(plain.pixels, bloom.pixels);
  const Image asked = render(scene("exr.toml", std::string(kSpot) + "exr = true\n"), "asked.exr");
  EXPECT_GT(max_diff(plain, asked), 0.05f);
}

// spp 4 (the accumulation path; spp 1 is drawn there too, not fused, when
// bloom is on) blooms as spp 1 does: bloom runs once on the averaged image.
// Antialiasing changes the sphere's edge pixels and so how much light it
// sends (measured: up to 6/255 on the probes), hence 8/255.
TEST_F(Bloom, MoreSamplesSameBloom) {
  const Image one = render(kData / "spot.toml", "one.png");
  const Image four = render(kData / "spot.toml", "four.png", {"--spp", "4"});
  const Image plain = render(kData / "spot_plain.toml", "plain4.png", {"--spp", "4"});
  ASSERT_EQ(four.width, 96);
  for (int d = 5; d < 20; ++d) {
    EXPECT_NEAR(one.at(48 + d, 31, 1), four.at(48 + d, 31, 1), 8.0f / 255) << d;
    if (d <= 12) EXPECT_GE(four.at(48 + d, 31, 1) - plain.at(48 + d, 31, 1), 4.0f / 255) << d;  // within the blur
  }
}

// A sequence's frames bloom as the still does (cli/sequence_cmd.cpp builds
// the same stage): frame 0 of --frames 0..1 equals `render` at time 0, bit
// for bit; --disable bloom there too equals no table.
TEST_F(Bloom, SequenceFramesEqualTheStill) {
  const Image still = render(kData / "spot.toml", "still.png");
  const RunResult r = run_marchstudio({"render", (kData / "spot.toml").string(), "--frames", "0..1", "-o",
                                       (dir / "f_%d.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_image(dir / "f_0.png").pixels, still.pixels);
  const Image plain = render(kData / "spot_plain.toml", "plain.png");
  const RunResult off = run_marchstudio({"render", (kData / "spot.toml").string(), "--frames", "0..0", "-o",
                                         (dir / "g_%d.png").string(), "--disable", "bloom"});
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(read_image(dir / "g_0.png").pixels, plain.pixels);
}

// A still drawn in tiles cannot blur across them: refused, one line.
TEST_F(Bloom, TiledStillIsRefused) {
  const RunResult r = run_marchstudio({"render", (kData / "spot.toml").string(), "-o", (dir / "t.png").string(),
                                       "--tile-still", "32"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("bloom needs the whole frame"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "t.png"));
  // Past the memory budget with the two bloom targets counted (4 GiB at
  // 96 bytes a pixel: 7000x7000 needs 4.4 GiB, 2.9 GiB without bloom) the
  // still would be tiled: refused before any GL, naming --size.
  const RunResult big = run_marchstudio({"render", (kData / "spot.toml").string(), "-o", (dir / "big.png").string(),
                                         "--size", "7000x7000"});
  EXPECT_EQ(big.exit_code, 2) << big.err;
  EXPECT_NE(big.err.find("bloom needs the whole frame"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("--size"), std::string::npos) << big.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "big.png"));
  // Without bloom the same tiled still renders.
  const RunResult ok = run_marchstudio({"render", (kData / "spot.toml").string(), "-o", (dir / "t.png").string(),
                                        "--tile-still", "32", "--disable", "bloom"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

TEST_F(Bloom, BadValuesAreOneLineErrors) {
  const struct {
    std::string body;
    std::string key;
  } cases[] = {
      {"threshold = nan\n", "post.bloom.threshold"},
      {"threshold = -1.0\n", "post.bloom.threshold"},
      {"intensity = -0.5\n", "post.bloom.intensity"},
      {"radius = 0.0\n", "post.bloom.radius"},
      {"radius = 1000.0\n", "post.bloom.radius"},
      {"scale = 0.01\n", "post.bloom.scale"},
      {"scale = 1.5\n", "post.bloom.scale"},
      {"passes = 0\n", "post.bloom.passes"},
      {"passes = 9\n", "post.bloom.passes"},
      {"passes = 1.5\n", "post.bloom.passes"},
      {"exr = 1\n", "post.bloom.exr"},
      {"radious = 4.0\n", "radious"},
  };
  const std::string plain = scene_text("");
  const int line = static_cast<int>(std::count(plain.begin(), plain.end(), '\n')) + 3;  // the key's line
  for (const auto& c : cases) {
    const auto toml = scene("bad.toml", c.body);
    const RunResult r = run_marchstudio({"render", toml.string(), "-o", (dir / "bad.png").string()});
    EXPECT_EQ(r.exit_code, 2) << c.body << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("bad.toml:" + std::to_string(line) + ":"), std::string::npos) << c.body << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << c.body << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.png")) << c.body;
  }
  // A key of [post] that is not a table it knows.
  write_file(dir / "bad.toml", read_file(kData / "spot_plain.toml") + "\n[post.blom]\nthreshold = 1.0\n");
  const RunResult r = run_marchstudio({"render", (dir / "bad.toml").string(), "-o", (dir / "bad.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("blom"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'bloom'"), std::string::npos) << r.err;
}

// `test` (suite/suite_run.cpp) draws the same bloom stage: a case on the
// scene equals render's image exactly (max 0), and the same case with
// disable = ["bloom"] fails against it (exit 1).
TEST_F(Bloom, TestCaseBloomsAsRenderDoes) {
  render(kData / "spot.toml", "ref.png");
  const std::string head = "[suite]\nname = \"b\"\n\n[[case]]\nname = \"spot\"\nscene = \"" +
                           (kData / "spot.toml").string() + "\"\nreference = \"ref.png\"\nmetric = \"max\"\n" +
                           "threshold = 0.0\n";
  write_file(dir / "ok.toml", head);
  const RunResult ok = run_marchstudio({"test", (dir / "ok.toml").string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  write_file(dir / "off.toml", head + "disable = [\"bloom\"]\n");
  const RunResult off = run_marchstudio({"test", (dir / "off.toml").string()});
  EXPECT_EQ(off.exit_code, 1) << off.out << off.err;
}

// The viewer (live/session.cpp) draws the same bloom stage: its first
// captured frame equals `render` of the scene within 1/255 (the viewer's
// frames are one sample, as render's here).
TEST_F(Bloom, ViewerShowsBloomAsRenderDoes) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  const Image want = render(kData / "spot.toml", "render.png");
  const Image plain = render(kData / "spot_plain.toml", "plain.png");
  auto proc = std::make_unique<BackgroundProcess>(
      std::vector<std::string>{"env", x_display(), MARCH_BIN, "view",
                               (kData / "spot.toml").string(), "--size", "96x64", "--paused", "--no-panel", "--log",
                               (dir / "log.txt").string(), "--capture-dir", (dir / "cap").string(), "--exit-after",
                               "30"},
      dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc->started());
  ASSERT_FALSE(wait_for_line(dir / "log.txt", "^capture 0 ", 30).empty()) << read_file(dir / "err.txt");
  const Image got = read_image(dir / "cap" / "frame_0.png");
  proc.reset();
  EXPECT_LE(max_abs_diff(got, want), 1.0 / 255.0);
  EXPECT_GT(max_abs_diff(got, plain), 0.1);  // and it is bloom that matches
}

}  // namespace
}  // namespace ms::test
