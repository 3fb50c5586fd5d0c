// Timed inputs in the viewer under Xvfb: a video input
// shows the frame of the viewer's time, as `render --time` does, and moves
// follows a new time; a music input's analyser texture, with no audio
// device to play to, is render's at the same time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>

#include "io/image_io.h"
#include "io/video.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// 8 frames of 8x6 at 4 fps, frame k a flat grey of 30 k + 10, lossless.
void make_clip(const fs::path& dir) {
  std::ofstream raw(dir / "frames.rgba", std::ios::binary);
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 8 * 6; ++i) {
      const char v = static_cast<char>(30 * k + 10);
      const char px[4] = {v, v, v, '\xff'};
      raw.write(px, 4);
    }
  raw.close();
  const std::string cmd = "cd '" + dir.string() +
                          "' && ffmpeg -hide_banner -loglevel error -nostdin -y -f rawvideo -pix_fmt rgba -s 8x6 -r 4 "
                          "-i frames.rgba -c:v ffv1 -pix_fmt bgra clip.mkv";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

const char* kVideoJson =
    "{\"Shader\": {\"info\": {\"name\": \"v\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
    "\"code\": \"void mainImage(out vec4 o, in vec2 f) { o = vec4(texture(iChannel0, vec2(0.5)).rgb, 1.0); }\", "
    "\"inputs\": [{\"id\": 1, \"ctype\": \"video\", \"channel\": 0, \"src\": \"/media/a/clip.mkv\"}], "
    "\"outputs\": []}]}}";

// The viewer's first frame at `time`, paused (its capture).
Image view_at(const fs::path& dir, const std::string& time, const std::string& tag, const std::string& json = "v.json",
              const std::string& size = "8x6") {
  const fs::path cap = dir / ("cap_" + tag), log = dir / ("log_" + tag + ".txt");
  BackgroundProcess p({"env", x_display(),
                       MARCH_BIN, "view", (dir / json).string(), "--size", size, "--paused", "--no-panel", "--time",
                       time, "--log", log.string(), "--capture-dir", cap.string(), "--max-frames", "3",
                       "--exit-after", "60"},
                      dir / "out.txt", dir / "err.txt");
  EXPECT_EQ(p.wait_exit(90), 0) << read_file(dir / "err.txt");
  return read_image(cap / "frame_0.png");
}

TEST(ViewerMedia, AVideoShowsTheFrameOfTheViewersTime) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH";
  if (find_on_path("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not on PATH";
  TempDir dir;
  make_clip(dir.path());
  write_file(dir / "v.json", kVideoJson);
  for (const auto& [time, frame] : {std::pair<std::string, int>{"0.3", 1}, {"1.6", 6}, {"2.3", 1}}) {
    const Image got = view_at(dir.path(), time, time);
    ASSERT_EQ(got.width, 8);
    const RunResult r = run_marchstudio({"render", "v.json", "--size", "8x6", "--time", time, "-o", "r.png"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image want = read_image(dir / "r.png");
    EXPECT_LE(max_abs_diff(got, want), 1.0 / 255.0) << "t = " << time << ": the viewer is not render --time";
    EXPECT_NEAR(got.at(4, 3, 0), (30 * frame + 10) / 255.0f, 1.0f / 255.0f) << "t = " << time;
  }
}

// Row 0 (the spectrum) across the image's lower half, row 1 (the wave) across its upper half.
const char* kMusicJson =
    "{\"Shader\": {\"info\": {\"name\": \"m\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
    "\"code\": \"void mainImage(out vec4 o, in vec2 f) { vec2 uv = f / iResolution.xy; "
    "float v = texture(iChannel0, vec2(uv.x, uv.y < 0.5 ? 0.25 : 0.75)).r; o = vec4(v, v, v, 1.0); }\", "
    "\"inputs\": [{\"id\": 1, \"ctype\": \"music\", \"channel\": 0, \"src\": \"/media/a/tone.wav\"}], "
    "\"outputs\": []}]}}";

TEST(ViewerMedia, MusicIsRendersAnalyserAtTheViewersTime) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH";
  if (find_on_path("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not on PATH";
  TempDir dir;
  const std::string cmd = "cd '" + dir.path().string() +
                          "' && ffmpeg -hide_banner -loglevel error -nostdin -y -f lavfi -i "
                          "'sine=frequency=2000:duration=3:sample_rate=44100' -ac 1 tone.wav";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  write_file(dir / "m.json", kMusicJson);
  const Image got = view_at(dir.path(), "1.5", "music", "m.json", "128x8");
  const RunResult r = run_marchstudio({"render", "m.json", "--size", "128x8", "--time", "1.5", "-o", "r.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image want = read_image(dir / "r.png");
  EXPECT_LE(max_abs_diff(got, want), 1.0 / 255.0) << "the viewer's analyser texture is not render's";
  float peak = 0;
  for (int x = 0; x < want.width; ++x) peak = std::max(peak, want.at(x, 6, 0));
  EXPECT_GT(peak, 0.5f) << "no spectrum peak: the test cannot see the texture";
}

// Playing: on ALSA's "null" device (no sound card needed) the viewer feeds
// the clip as time runs; with none, or a device that is not there, it says
// why it is silent and goes on rendering.
TEST(ViewerMedia, MusicPlaysWhereADeviceOpensAndIsSilentWhereNot) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH";
  if (find_on_path("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not on PATH";
  TempDir dir;
  const std::string cmd = "cd '" + dir.path().string() +
                          "' && ffmpeg -hide_banner -loglevel error -nostdin -y -f lavfi -i "
                          "'sine=frequency=440:duration=1:sample_rate=22050' -ac 1 tone.wav";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  write_file(dir / "m.json", kMusicJson);
  auto run_with = [&](const std::string& device) {
    const fs::path log = dir / ("log_" + device + ".txt");
    BackgroundProcess p({"env", x_display(),
                         MARCH_BIN, "view", (dir / "m.json").string(), "--size", "64x8", "--no-panel",
                         "--audio-device", device, "--log", log.string(), "--exit-after", "1.5"},
                        dir / "out.txt", dir / "err.txt");
    EXPECT_EQ(p.wait_exit(60), 0) << read_file(dir / "err.txt");
    return read_file(log);
  };
  const std::string played = run_with("null");
  EXPECT_NE(played.find("audio playing null"), std::string::npos) << played;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(played, m, std::regex("audio written ([0-9]+) restarts ([0-9]+)"))) << played;
  // About the 1.5 s that ran (less the start-up), 0.15 s ahead at most, in one go.
  EXPECT_GT(std::stol(m[1]), 22050 / 2) << "under half a second of sound for 1.5 s of time";
  EXPECT_LT(std::stol(m[1]), 22050 * 17 / 10) << "more sound than time";
  EXPECT_LE(std::stoi(m[2]), 2) << "playback kept restarting: it does not follow time";
  for (const std::string device : {"none", "nosuchdevice"}) {
    const std::string silent = run_with(device);
    EXPECT_NE(silent.find("audio silent -- "), std::string::npos) << silent;
    EXPECT_EQ(silent.find("audio written"), std::string::npos) << silent;
    EXPECT_NE(silent.find("exit frames="), std::string::npos) << silent;
  }
}

}  // namespace
}  // namespace ms::test
