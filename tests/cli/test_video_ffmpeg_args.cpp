// How paths reach ffmpeg and ffprobe, through the real binary: every path
// is an absolute file: URL with -protocol_whitelist file, so a media
// directory named "-report:" is not an option (no report file appears), a
// --video name with ':' is not a protocol; and every child has a bound of
// its own, so a concat script naming a FIFO is refused, not waited for.
// Tests skip when ffmpeg is not installed.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <string>

#include "io/video.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

bool have_ffmpeg() { return !find_on_path("ffmpeg").empty(); }

std::string video_json(const std::string& src) {
  return "{\"Shader\": {\"info\": {\"name\": \"v\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
         "\"code\": \"void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); }\", "
         "\"inputs\": [{\"id\": 1, \"ctype\": \"video\", \"channel\": 0, \"src\": \"" + src +
         "\", \"sampler\": {\"filter\": \"linear\", \"wrap\": \"clamp\", \"vflip\": \"true\", \"srgb\": \"false\"}}], "
         "\"outputs\": []}]}}";
}

// A 2 s, 8x6 FFV1 clip at dir/rel (written through a file: URL: the name may hold ':').
void make_clip(const fs::path& dir, const std::string& rel) {
  const std::string cmd = "cd '" + dir.string() +
                          "' && ffmpeg -hide_banner -loglevel error -nostdin -y -f lavfi -i testsrc=size=8x6:rate=4 "
                          "-t 2 -c:v ffv1 'file:" + rel + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

bool any_report(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("ffprobe-", 0) == 0 || name.rfind("ffmpeg-", 0) == 0) return true;
  }
  return false;
}

TEST(VideoFfmpegArgs, AMediaDirNamedLikeAnOptionIsAPath) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  fs::create_directories(dir / "-report:");
  make_clip(dir.path(), "-report:/clip.mkv");
  write_file(dir / "v.json", video_json("/media/a/clip.mkv"));
  // A scene's media_dir, relative to a scene named without a directory.
  write_file(dir / "t.toml", "[scene]\nshadertoy = \"v.json\"\n[shadertoy]\nmedia_dir = \"-report:\"\n");
  const RunResult r = run_marchstudio({"render", "t.toml", "--size", "8x6", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "o.png"));
  EXPECT_FALSE(any_report(dir.path())) << "ffprobe took the media path for -report";
  const RunResult flag =
      run_marchstudio({"render", "v.json", "--media-dir=-report:", "--size", "8x6", "-o", "f.png"}, dir.path());
  EXPECT_EQ(flag.exit_code, 0) << flag.err;
  EXPECT_FALSE(any_report(dir.path()));
}

TEST(VideoFfmpegArgs, ANameWithAColonIsAFileNotAProtocol) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  make_clip(dir.path(), "c:1.mkv");
  write_file(dir / "v.json", video_json("/media/a/c:1.mkv"));
  const RunResult in = run_marchstudio({"render", "v.json", "--media-dir", ".", "--size", "8x6", "-o", "o.png"},
                                       dir.path());
  EXPECT_EQ(in.exit_code, 0) << in.err;
  write_file(dir / "s.glsl", "void mainImage(out vec4 o, in vec2 f) { o = vec4(f.x / 8.0, iTime, 0.0, 1.0); }\n");
  const RunResult out = run_marchstudio(
      {"render", "s.glsl", "--size", "8x6", "--frames", "0..2", "-o", "fr/f_%04d.png", "--video", "v:1.mp4"},
      dir.path());
  EXPECT_EQ(out.exit_code, 0) << out.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "v:1.mp4"));
  EXPECT_GT(fs::file_size(dir / "v:1.mp4"), 0u);
}

TEST(VideoFfmpegArgs, AConcatScriptNamingAFifoIsRefusedWithinTheProbeBound) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "f.mkv").c_str(), 0600), 0);
  write_file(dir / "c.mkv", "ffconcat version 1.0\nfile f.mkv\n");
  write_file(dir / "c.json", video_json("/media/a/c.mkv"));
  const auto t0 = std::chrono::steady_clock::now();
  // The shell's timeout ends a hang (exit 124) instead of the test run.
  const RunResult r = run_marchstudio({"render", "c.json", "--media-dir", ".", "--size", "8x6", "-o", "o.png"},
                                      dir.path(), "timeout -k 5 90 ");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("c.mkv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("within 10 s"), std::string::npos) << r.err;
  EXPECT_LT(s, 60.0);
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

}  // namespace
}  // namespace ms::test
