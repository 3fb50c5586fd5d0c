// Video inputs through the real binary: the test makes its own
// lossless clip with ffmpeg (8 frames of 8x6 at 4 fps, each frame a
// distinct colour on top and another below, RGB straight through FFV1 in
// Matroska, or lossless VP9 as gbrp in WebM), so every pixel is exact:
// the shader shows the channel texel for texel and each --time must show
// frame floor(fmod(t, 2 s) x 4), upright (vflip), looping; a sequence's
// frames equal the stills at their times, a shard that starts mid-clip
// included; without ffprobe ffmpeg's own report is parsed; a missing file,
// an undecodable one and ffmpeg not on PATH are one-line errors, exit 2,
// no output. Tests that need ffmpeg skip when it is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "io/video.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

constexpr int kW = 8, kH = 6, kFrames = 8;

using Rgb = std::array<int, 3>;
Rgb top_colour(int k) { return {k * 30 + 10, 255 - k * 30, (k * 67) % 256}; }
Rgb bottom_colour(int k) { return {(k * 97) % 256, k * 20 + 5, 200 - k * 10}; }

bool have_ffmpeg() { return !find_on_path("ffmpeg").empty(); }

bool have_encoder(const std::string& name) {
  return std::system(("ffmpeg -hide_banner -encoders 2>/dev/null | grep -q ' " + name + " '").c_str()) == 0;
}

// The clip, encoded losslessly by `codec_args` into dir/name.
void make_clip(const TempDir& dir, const std::string& name, const std::string& codec_args) {
  std::ofstream raw(dir / "frames.rgba", std::ios::binary);
  for (int k = 0; k < kFrames; ++k)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const Rgb c = y < kH / 2 ? top_colour(k) : bottom_colour(k);
        const char px[4] = {static_cast<char>(c[0]), static_cast<char>(c[1]), static_cast<char>(c[2]), '\xff'};
        raw.write(px, 4);
      }
  raw.close();
  const std::string cmd = "cd '" + dir.path().string() +
                          "' && ffmpeg -hide_banner -loglevel error -nostdin -y -f rawvideo -pix_fmt rgba -s 8x6 "
                          "-r 4 -i frames.rgba " + codec_args + " " + name;
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

void make_mkv(const TempDir& dir, const std::string& name = "clip.mkv") {
  make_clip(dir, name, "-c:v ffv1 -pix_fmt bgra");
}

// The Image pass shows iChannel0 texel for texel; pixel (0, 0) at the
// bottom left shows iChannelResolution[0].xy / 255.
std::string video_json(const std::string& src, const std::string& sampler = "\"vflip\": \"true\"") {
  return "{\"Shader\": {\"info\": {\"name\": \"v\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
         "\"code\": \"void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); "
         "if (f.x < 1.0 && f.y < 1.0) o = vec4(iChannelResolution[0].xy / 255.0, 0.0, 1.0); }\", "
         "\"inputs\": [{\"id\": 1, \"ctype\": \"video\", \"channel\": 0, \"src\": \"" + src +
         "\", \"sampler\": {\"filter\": \"linear\", \"wrap\": \"clamp\", " + sampler + ", \"srgb\": \"false\"}}], "
         "\"outputs\": []}]}}";
}

int byte(const Image& img, int x, int y, int c) { return static_cast<int>(std::lround(img.at(x, y, c) * 255.0f)); }

// The rendered image is frame k of the clip, upright (row 0 its top), to
// within 1/255 (the codec is lossless: the bytes come through as they are).
void expect_frame(const fs::path& png, int k, const std::string& what) {
  const Image img = read_image(png);
  ASSERT_EQ(img.width, kW) << what;
  ASSERT_EQ(img.height, kH) << what;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (x == 0 && y == kH - 1) continue;  // the resolution pixel
      const Rgb want = y < kH / 2 ? top_colour(k) : bottom_colour(k);
      for (int c = 0; c < 3; ++c)
        ASSERT_LE(std::abs(byte(img, x, y, c) - want[c]), 1) << what << ": frame " << k << " pixel " << x << "," << y;
    }
  EXPECT_EQ(byte(img, 0, kH - 1, 0), kW) << what << ": iChannelResolution.x";
  EXPECT_EQ(byte(img, 0, kH - 1, 1), kH) << what << ": iChannelResolution.y";
}

// Frame floor(fmod(t, 2) x 4): the clip is 2 s long and loops.
int frame_at(double t) { return static_cast<int>(std::floor(std::fmod(t, 2.0) * 4.0 + 1e-4)); }

RunResult render_at(const TempDir& dir, const std::string& json, const std::string& time, const std::string& out,
                    const std::string& prefix = {}) {
  return run_marchstudio({"render", json, "--media-dir", ".", "--size", "8x6", "--time", time, "-o", out},
                         dir.path(), prefix);
}

TEST(VideoInput, FrameAtITimeLoopsFromTheStart) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  make_mkv(dir);
  write_file(dir / "v.json", video_json("/media/a/clip.mkv"));
  const std::vector<std::pair<std::string, int>> times = {
      {"0", 0}, {"0.2", 0}, {"0.25", 1}, {"0.3", 1}, {"1.75", 7}, {"1.99", 7},
      {"2", 0}, {"2.6", 2}, {"9.5", 6}, {"0.5", 2}};  // the last after a later time: a fresh process each
  for (const auto& [t, k] : times) {
    const RunResult r = render_at(dir, "v.json", t, "o.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_frame(dir / "o.png", k, "--time " + t);
  }
}

TEST(VideoInput, LosslessWebmShowsTheSameFrames) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  if (!have_encoder("libvpx-vp9")) GTEST_SKIP() << "this ffmpeg has no libvpx-vp9 encoder";
  TempDir dir;
  make_clip(dir, "clip.webm", "-c:v libvpx-vp9 -lossless 1 -pix_fmt gbrp");
  write_file(dir / "v.json", video_json("/media/a/clip.webm"));
  for (const auto& [t, k] : std::vector<std::pair<std::string, int>>{{"0", 0}, {"1.3", 5}, {"3.8", 7}}) {
    const RunResult r = render_at(dir, "v.json", t, "o.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_frame(dir / "o.png", k, "webm --time " + t);
  }
}

// A sequence streams (one ffmpeg decoding forward, restarted at the loop);
// a still seeks. Each frame is the still at its time, and a shard that
// starts mid-clip (a seek into VP9's inter frames when it is there) too.
TEST(VideoInput, SequenceFramesEqualStills) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  const bool webm = have_encoder("libvpx-vp9");
  if (webm) make_clip(dir, "clip.webm", "-c:v libvpx-vp9 -lossless 1 -pix_fmt gbrp");
  else make_mkv(dir, "clip.webm");  // Matroska under WebM's name: ffmpeg reads either
  write_file(dir / "v.json", video_json("/media/a/clip.webm"));
  RunResult r = run_marchstudio({"render", "v.json", "--media-dir", ".", "--size", "8x6", "--frames", "0..24", "--fps",
                                 "10", "-o", "f_%02d.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_marchstudio({"render", "v.json", "--media-dir", ".", "--size", "8x6", "--frames", "13..17", "--fps", "10",
                       "-o", "s_%02d.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (int i = 0; i <= 24; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "f_%02d.png", i);
    expect_frame(dir / name, frame_at(i / 10.0), "sequence frame " + std::to_string(i));
    if (i >= 13 && i <= 17) {
      std::snprintf(name, sizeof name, "s_%02d.png", i);
      expect_frame(dir / name, frame_at(i / 10.0), "shard frame " + std::to_string(i));
    }
  }
  for (int i : {3, 12, 19, 21}) {
    char t[32], name[32];
    std::snprintf(t, sizeof t, "%.17g", i / 10.0);
    std::snprintf(name, sizeof name, "f_%02d.png", i);
    r = render_at(dir, "v.json", t, "still.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_image(dir / "still.png").pixels, read_image(dir / name).pixels) << "frame " << i;
  }
}

TEST(VideoInput, VflipFalseShowsTheFileRowsUpsideDown) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  make_mkv(dir);
  write_file(dir / "v.json", video_json("/media/a/clip.mkv", "\"vflip\": \"false\""));
  const RunResult r = render_at(dir, "v.json", "0.5", "o.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "o.png");
  EXPECT_EQ(byte(img, 3, 0, 0), bottom_colour(2)[0]);  // the file's bottom row at the top
  EXPECT_EQ(byte(img, 3, kH - 1, 1), top_colour(2)[1]);
}

// Without ffprobe, ffmpeg's own report gives the size, rate and duration.
TEST(VideoInput, WithoutFfprobeFfmpegsReportIsRead) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir, bin;
  make_mkv(dir);
  fs::create_symlink(find_on_path("ffmpeg"), bin / "ffmpeg");
  write_file(dir / "v.json", video_json("/media/a/clip.mkv"));
  for (const auto& [t, k] : std::vector<std::pair<std::string, int>>{{"0.75", 3}, {"2.25", 1}}) {
    const RunResult r = render_at(dir, "v.json", t, "o.png", "PATH='" + bin.path().string() + "' ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_frame(dir / "o.png", k, "no ffprobe, --time " + t);
  }
}

bool one_line(const std::string& err) { return std::count(err.begin(), err.end(), '\n') == 1; }

TEST(VideoInput, MissingFileIsAnErrorOrAStandIn) {
  TempDir dir;
  write_file(dir / "v.json", video_json("/media/a/gone.webm"));
  RunResult r = render_at(dir, "v.json", "1", "o.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("video '/media/a/gone.webm' is not in the media directory"), std::string::npos) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
  r = run_marchstudio({"render", "v.json", "--media-dir", ".", "--missing-media", "black", "--size", "8x6", "-o",
                       "o.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("video '/media/a/gone.webm' is missing; black stands in"), std::string::npos) << r.err;
  const Image img = read_image(dir / "o.png");
  EXPECT_EQ(byte(img, 4, 2, 0) + byte(img, 4, 2, 1) + byte(img, 4, 2, 2), 0);
  EXPECT_EQ(byte(img, 0, kH - 1, 0), 1);  // the stand-in's resolution, 1x1
  r = run_marchstudio({"render", "v.json", "--media-dir", ".", "--missing-media", "noise", "--size", "8x6", "-o",
                       "n.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("a still of generated noise stands in"), std::string::npos) << r.err;
}

TEST(VideoInput, UndecodableFileIsOneLineNamingIt) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  write_file(dir / "bad.webm", "not a video, only some bytes that ffmpeg cannot read as one");
  write_file(dir / "v.json", video_json("/media/a/bad.webm"));
  const RunResult r = render_at(dir, "v.json", "0", "o.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bad.webm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot decode the video file"), std::string::npos) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

TEST(VideoInput, FfmpegNotOnPathIsOneLine) {
  TempDir dir, empty;
  write_file(dir / "clip.webm", "whatever: ffmpeg is looked for first");
  write_file(dir / "v.json", video_json("/media/a/clip.webm"));
  const RunResult r = render_at(dir, "v.json", "0", "o.png", "PATH='" + empty.path().string() + "' ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("video inputs need ffmpeg"), std::string::npos) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

}  // namespace
}  // namespace ms::test
