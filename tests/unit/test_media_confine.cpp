// The pieces media confinement and ffmpeg's paths are made of:
// media_roots and confine_media (preprocess/confine.h), the VS Code cube
// wildcard's six files (io/cube_faces.h) and ffmpeg_file_url (io/video.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "files.h"
#include "io/cube_faces.h"
#include "io/video.h"
#include "preprocess/confine.h"

namespace ms {
namespace {

namespace fs = std::filesystem;

class MediaRoots : public ::testing::Test {
 protected:
  void SetUp() override {
    tmp = fs::canonical(tmp_dir.path());
    fs::create_directories(tmp / "scene");
    fs::create_directories(tmp / "media");
    fs::create_directories(tmp / "outside");
    std::ofstream(tmp / "outside" / "x.png") << "x";
    fs::create_symlink("../outside/x.png", tmp / "media" / "link.png");
  }
  // The message of the error confine_media throws, or "" when it allows `f`.
  std::string refusal(const fs::path& f, const std::vector<fs::path>& roots) {
    try {
      confine_media(f, roots, "texture 'x'", "s.toml", "Image iChannel0");
    } catch (const Error& e) {
      EXPECT_EQ(e.info().code, Exit::bad_input);
      return e.info().what;
    }
    return {};
  }
  test::TempDir tmp_dir;
  fs::path tmp;
};

TEST_F(MediaRoots, TheScenesFolderTheMediaFlagAndAllowIncludeOnly) {
  const std::vector<fs::path> roots = media_roots(tmp / "scene" / "s.toml", tmp / "media", {});
  EXPECT_EQ(refusal(tmp / "scene" / "a.png", roots), "");  // need not exist
  EXPECT_EQ(refusal(tmp / "media" / "b.png", roots), "");
  EXPECT_NE(refusal(tmp / "scene" / ".." / "outside" / "x.png", roots), "");
  const std::string why = refusal(tmp / "media" / "link.png", roots);  // judged where it leads
  EXPECT_NE(why.find("resolves to"), std::string::npos) << why;
  EXPECT_NE(why.find("outside/x.png"), std::string::npos) << why;
  EXPECT_NE(why.find("outside the directories media may read"), std::string::npos) << why;
  // No --media-dir: the media folder is not a root by itself.
  EXPECT_NE(refusal(tmp / "media" / "b.png", media_roots(tmp / "scene" / "s.toml", {}, {})), "");
  // --allow-include widens it.
  EXPECT_EQ(refusal(tmp / "media" / "link.png", media_roots(tmp / "scene" / "s.toml", {}, {tmp / "outside"})), "");
}

TEST(CubeWildcard, NamesTheSixFacesInGlsOrder) {
  const auto f = cube_wildcard_files("/d/sky_{}.png");
  EXPECT_EQ(f[0], "/d/sky_px.png");
  EXPECT_EQ(f[1], "/d/sky_nx.png");
  EXPECT_EQ(f[5], "/d/sky_nz.png");
  EXPECT_TRUE(cube_wildcard_files("/d/sky.png")[0].empty());
}

TEST(FfmpegFileUrl, IsAbsoluteAndVerbatim) {
  const std::string cwd = fs::current_path().string();
  EXPECT_EQ(ffmpeg_file_url("-report:/c.mkv"), "file:" + cwd + "/-report:/c.mkv");
  EXPECT_EQ(ffmpeg_file_url("/a/v:1 %20.mp4"), "file:/a/v:1 %20.mp4");  // ffmpeg's file: does not percent-decode
}

}  // namespace
}  // namespace ms
