// Fingerprinted frames (pipeline/fingerprint.h): a rerun keeps a frame only when
// it carries this run's fingerprint for it; others render again with one
// summary line; --force renders everything; `info` reads it back.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>

#include "io/image_io.h"
#include "run.h"

using namespace ms::test;
namespace fs = std::filesystem;

namespace {

const std::string kSeed = (source_dir() / "scenes/seed.toml").string();
const std::string kColumns = (source_dir() / "scenes/columns.toml").string();

RunResult frames(const std::string& scene, const fs::path& dir, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"render", scene, "--frames", "0..3", "--size", "32x18", "-o", "f_%d.png"};
  args.insert(args.end(), more.begin(), more.end());
  return run_marchstudio(args, dir);
}

int rendered(const RunResult& r) {
  const std::regex line(R"(frame \d+ rendered in)");
  return static_cast<int>(std::distance(std::sregex_iterator(r.err.begin(), r.err.end(), line), std::sregex_iterator()));
}

std::string fingerprint(const fs::path& dir, const std::string& file) {
  const RunResult r = run_marchstudio({"info", "--fingerprint", file}, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

}  // namespace

TEST(Fingerprint, AnotherScenesFramesAreRenderedAgainNotShipped) {
  TempDir dir;
  ASSERT_EQ(frames(kSeed, dir.path()).exit_code, 0);
  const std::string seed0 = fingerprint(dir.path(), "f_0.png");
  ASSERT_TRUE(std::regex_match(seed0, std::regex("[0-9a-f]{32}\n"))) << seed0;

  RunResult r = frames(kColumns, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("4 frames on disk are not this run's (4 made from other inputs or settings, 0 with no "
                       "fingerprint): rendering them again"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(rendered(r), 4) << r.err;
  EXPECT_NE(fingerprint(dir.path(), "f_0.png"), seed0);

  // The same command again keeps them all; --force renders them all.
  r = frames(kColumns, dir.path());
  EXPECT_NE(r.err.find("4 already complete, 0 to render"), std::string::npos) << r.err;
  EXPECT_EQ(rendered(r), 0);
  r = frames(kColumns, dir.path(), {"--force"});
  EXPECT_EQ(rendered(r), 4) << r.err;
  EXPECT_EQ(r.err.find("not this run's"), std::string::npos) << r.err;
}

TEST(Fingerprint, SettingsTimeAndUnmarkedFilesCount) {
  TempDir dir;
  ASSERT_EQ(frames(kSeed, dir.path()).exit_code, 0);
  // Other samples per pixel: other frames.
  RunResult r = frames(kSeed, dir.path(), {"--spp", "2"});
  EXPECT_EQ(rendered(r), 4) << r.err;
  // Another frame rate moves every frame but 0 in time.
  r = frames(kSeed, dir.path(), {"--spp", "2", "--fps", "30"});
  EXPECT_EQ(rendered(r), 3) << r.err;
  // A complete frame of the right size that marchstudio did not mark.
  ms::Image img;
  img.width = 32;
  img.height = 18;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.assign(32 * 18 * 4, 0.5f);
  ms::write_image(img, dir / "f_2.png");
  r = frames(kSeed, dir.path(), {"--spp", "2", "--fps", "30"});
  EXPECT_NE(r.err.find("1 frame on disk is not this run's (0 made from other inputs or settings, 1 with no "
                       "fingerprint)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(rendered(r), 1) << r.err;
  EXPECT_FALSE(fingerprint(dir.path(), "f_2.png").empty());
}

TEST(Fingerprint, EveryFormatKeepsItAndInfoShowsIt) {
  TempDir dir;
  for (const char* ext : {"png", "jpg", "tif", "exr"}) {
    const RunResult r = run_marchstudio({"render", kSeed, "--size", "16x9", "-o", std::string("s.") + ext}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::string png = fingerprint(dir.path(), "s.png");
  EXPECT_TRUE(std::regex_match(png, std::regex("[0-9a-f]{32}\n"))) << png;
  EXPECT_EQ(fingerprint(dir.path(), "s.jpg"), png);  // same shaders and settings: the same fingerprint
  EXPECT_EQ(fingerprint(dir.path(), "s.tif"), png);
  EXPECT_NE(fingerprint(dir.path(), "s.exr"), png);  // float output: another post pass
  RunResult r = run_marchstudio({"info", "s.tif"}, dir.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("s.tif: 16x9, 3 channels (R,G,B), uint8, tiff\n  fingerprint: " + png), std::string::npos)
      << r.out;
  // No fingerprint: exit 1 with --fingerprint; a bad file: exit 2, one line.
  ms::Image img;
  img.width = img.height = 2;
  img.channels = {"R", "G", "B"};
  img.pixels.assign(12, 0.0f);
  ms::write_image(img, dir / "plain.png");
  r = run_marchstudio({"info", "--fingerprint", "plain.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("plain.png: no marchstudio fingerprint"), std::string::npos) << r.err;
  r = run_marchstudio({"info", "missing.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  // --force on a still is refused: it would do nothing.
  r = run_marchstudio({"render", kSeed, "--size", "16x9", "-o", "t.png", "--force"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "t.png"));
}
