// `render --frames`: exact per-frame time, keyframes reaching the image,
// shards that together render every frame once, resume after SIGKILL,
// a clean stop on SIGTERM, ffmpeg handling, and clear errors for bad input.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <set>
#include <thread>

#include "io/image_io.h"
#include "io/sequence.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// iTime, iFrame and iTimeDelta straight into the pixels (EXR keeps floats).
const char* kClock = R"(void mainImage(out vec4 c, in vec2 f) {
  c = vec4(iTime, float(iFrame), iTimeDelta, 1.0);
}
)";

// Enough work per pixel that a frame takes a while on llvmpipe (~0.2 s at 160x90).
const char* kSlow = R"(void mainImage(out vec4 c, in vec2 f) {
  float a = 0.0;
  for (int i = 0; i < 20000; ++i) a += sin(f.x * 0.01 + float(i) * 0.001 + iTime);
  c = vec4(fract(a), fract(iTime), 0.5, 1.0);
}
)";

int count_lines_with(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

std::vector<std::string> temp_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) out.push_back(e.path().filename().string());
  return out;
}

TEST(Sequence, FrameTimeIsExactlyFrameOverFps) {
  TempDir dir;
  write_file(dir / "clock.glsl", kClock);
  for (const auto& [frames, fps, first, last] :
       {std::tuple{"0..5", "30", 0, 5}, std::tuple{"9998..10001", "29.97", 9998, 10001}}) {
    RunResult r = run_marchstudio({"render", "clock.glsl", "--frames", frames, "--fps", fps, "--size", "4x2", "-o",
                                   "t_%05d.exr"},
                                  dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const double f_per_s = std::stod(fps);
    for (int f = first; f <= last; ++f) {
      const Image img = read_image(dir / ("t_" + std::string(5 - std::to_string(f).size(), '0') + std::to_string(f) + ".exr"));
      EXPECT_EQ(img.at(1, 1, 0), static_cast<float>(static_cast<double>(f) / f_per_s)) << "iTime, frame " << f;
      EXPECT_EQ(img.at(1, 1, 1), static_cast<float>(f)) << "iFrame";
      EXPECT_EQ(img.at(1, 1, 2), static_cast<float>(1.0 / f_per_s)) << "iTimeDelta";
      EXPECT_NE(r.out.find("t_" + std::string(5 - std::to_string(f).size(), '0') + std::to_string(f) + ".exr"),
                std::string::npos)
          << "each written frame's path is printed";
    }
  }
}

// A keyframed material colour and camera reach the image, and a sequence
// frame equals `render --time` at that frame's time, pixel for pixel.
TEST(Sequence, KeyframesAnimateTheSceneAndMatchSingleRenders) {
  TempDir dir;
  // The map next to the scene: includes may only read the scene's directory.
  write_file(dir / "seed.glsl", read_file(source_dir() / "scenes" / "seed.glsl"));
  write_file(dir / "anim.toml", "[scene]\nmap = \"seed.glsl\"\n[camera]\nposition = [0, 1.6, -5]\n"
                                "target = [0, 0.8, 0]\n[render]\nwidth = 48\nheight = 27\n[[lights]]\n"
                                "position = [4, 5, -1.5]\n[[materials]]\nname = \"floor\"\n[[materials]]\n"
                                "name = \"ball\"\ncolor = [1, 0, 0]\n"
                                "[[animation]]\ntarget = \"materials[1].color\"\n"
                                "keys = [[0, 1, 0, 0], [1, 0, 0, 1]]\n"
                                "[[animation]]\ntarget = \"camera.position\"\ninterpolation = \"smooth\"\n"
                                "keys = [[0, 0, 1.6, -5], [1, 1, 1.6, -4.5]]\n");
  RunResult r = run_marchstudio({"render", "anim.toml", "--frames", "0..2", "--fps", "2", "-o", "a_%d.exr"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  RunResult one = run_marchstudio({"render", "anim.toml", "--time", "0.5", "-o", "single.exr"}, dir.path());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const Image a0 = read_image(dir / "a_0.exr"), a1 = read_image(dir / "a_1.exr"), a2 = read_image(dir / "a_2.exr");
  const Image single = read_image(dir / "single.exr");
  EXPECT_EQ(a1.pixels, single.pixels) << "frame 1 at 2 fps is t = 0.5";
  // The ball's centre (the camera moves little): red at t=0, blue at t=1.
  const int cx = 24, cy = 16;
  EXPECT_GT(a0.at(cx, cy, 0), 3 * a0.at(cx, cy, 2)) << "red ball at t=0";
  EXPECT_GT(a2.at(cx, cy, 2), 3 * a2.at(cx, cy, 0)) << "blue ball at t=1";
}

// A program keeps its uniforms and a frame sends only what changed
// (render/program.h): a value that leaves and comes back must be sent again.
// The ball goes red, blue, red and the camera out and back, so frame 2 is
// frame 0, and each frame is its single render.
TEST(Sequence, AValueThatComesBackIsSentAgain) {
  TempDir dir;
  write_file(dir / "seed.glsl", read_file(source_dir() / "scenes" / "seed.glsl"));
  write_file(dir / "anim.toml", "[scene]\nmap = \"seed.glsl\"\n[camera]\nposition = [0, 1.6, -5]\n"
                                "target = [0, 0.8, 0]\n[render]\nwidth = 32\nheight = 18\n[[lights]]\n"
                                "position = [4, 5, -1.5]\n[[materials]]\nname = \"floor\"\n[[materials]]\n"
                                "name = \"ball\"\ncolor = [1, 0, 0]\n"
                                "[[animation]]\ntarget = \"materials[1].color\"\n"
                                "keys = [[0, 1, 0, 0], [1, 0, 0, 1], [2, 1, 0, 0]]\n"
                                "[[animation]]\ntarget = \"camera.position\"\n"
                                "keys = [[0, 0, 1.6, -5], [1, 1, 1.6, -4.5], [2, 0, 1.6, -5]]\n");
  for (const char* d : {"fragment", "compute"}) {
    RunResult r = run_marchstudio({"render", "anim.toml", "--frames", "0..2", "--fps", "1", "--dispatch", d, "-o",
                                   std::string(d) + "_%d.exr"},
                                  dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image a0 = read_image(dir / (std::string(d) + "_0.exr")), a1 = read_image(dir / (std::string(d) + "_1.exr"));
    const Image a2 = read_image(dir / (std::string(d) + "_2.exr"));
    EXPECT_NE(a0.pixels, a1.pixels) << d;
    EXPECT_EQ(a2.pixels, a0.pixels) << d << ": frame 2 holds frame 0's values";
    RunResult one = run_marchstudio({"render", "anim.toml", "--time", "1", "--dispatch", d, "-o", "one.exr"}, dir.path());
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(read_image(dir / "one.exr").pixels, a1.pixels) << d;
  }
}

void expect_shards_cover(const std::string& mode) {
  TempDir dir;
  write_file(dir / "clock.glsl", kClock);
  std::multiset<std::string> printed;
  for (int i = 0; i < 3; ++i) {
    RunResult r = run_marchstudio({"render", "clock.glsl", "--frames", "3..13", "--size", "2x2", "-o", "s_%02d.exr",
                                   "--shard", std::to_string(i) + "/3", "--shard-mode", mode},
                                  dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (size_t a = 0, b; (b = r.out.find('\n', a)) != std::string::npos; a = b + 1) printed.insert(r.out.substr(a, b - a));
  }
  EXPECT_EQ(printed.size(), 11u) << "11 frames written in all";
  for (int f = 3; f <= 13; ++f) {
    const std::string name = "s_" + std::string(f < 10 ? "0" : "") + std::to_string(f) + ".exr";
    EXPECT_EQ(printed.count(name), 1u) << name << " written by exactly one shard";
    EXPECT_TRUE(frame_is_complete(dir / name, 2, 2)) << name;
  }
  EXPECT_EQ(count_files(dir.path(), "s_"), 11);
}

TEST(Sequence, StrideShardsRenderEachFrameOnce) { expect_shards_cover("stride"); }
TEST(Sequence, ChunkShardsRenderEachFrameOnce) { expect_shards_cover("chunk"); }

TEST(Sequence, ResumesAfterSigkill) {
  TempDir dir;
  write_file(dir / "slow.glsl", kSlow);
  const std::vector<std::string> args = {"render", "slow.glsl", "--frames", "0..23", "--size", "160x90",
                                         "-o", "k_%03d.png"};
  const pid_t pid = spawn_marchstudio(args, dir.path(), "first.log");
  wait_for_files(dir.path(), "k_", 3, pid);
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const int before = count_files(dir.path(), "k_");
  ASSERT_LT(before, 24) << "killed halfway, not at the end";
  // What a kill during a write leaves behind (the name write_image uses).
  write_file(dir / ".k_023.tmp99999.png", "half a png");
  for (int f = 0; f < 24; ++f) {
    const fs::path p = dir / ("k_" + std::string(f < 10 ? "00" : "0") + std::to_string(f) + ".png");
    if (fs::exists(p)) EXPECT_TRUE(frame_is_complete(p, 160, 90)) << "no half-written frame: " << p;
  }

  RunResult r = run_marchstudio(args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_lines_with(r.err, " skipped: "), before) << r.err;
  EXPECT_EQ(count_lines_with(r.err, " rendered in "), 24 - before) << r.err;
  EXPECT_NE(r.err.find("removed .k_023.tmp99999.png"), std::string::npos) << r.err;
  for (int f = 0; f < 24; ++f) {
    const fs::path p = dir / ("k_" + std::string(f < 10 ? "00" : "0") + std::to_string(f) + ".png");
    EXPECT_TRUE(frame_is_complete(p, 160, 90)) << p;
  }
  EXPECT_EQ(temp_files(dir.path()), std::vector<std::string>{}) << "no temporaries remain";
}

TEST(Sequence, SigtermStopsCleanlyAndKeepsRenderedFrames) {
  TempDir dir;
  write_file(dir / "slow.glsl", kSlow);
  const pid_t pid = spawn_marchstudio({"render", "slow.glsl", "--frames", "0..23", "--size", "160x90", "-o", "t_%03d.png"},
                          dir.path(), "run.log");
  wait_for_files(dir.path(), "t_", 2, pid);
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  const std::string log = read_file(dir / "run.log");
  EXPECT_NE(log.find("stopped by SIGTERM"), std::string::npos) << log;
  EXPECT_EQ(count_files(dir.path(), "t_"), count_lines_with(log, " rendered in ")) << "every rendered frame is written";
  EXPECT_EQ(temp_files(dir.path()), std::vector<std::string>{});
}

TEST(Sequence, NoWriteRendersButWritesNothing) {
  TempDir dir;
  write_file(dir / "clock.glsl", kClock);
  RunResult r = run_marchstudio({"render", "clock.glsl", "--frames", "0..3", "--size", "2x2", "-o", "n_%d.png",
                                 "--no-write"},
                                dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_lines_with(r.err, " rendered in "), 4) << r.err;
  EXPECT_EQ(count_files(dir.path(), "n_"), 0);
}

// Each bad flag: exit 2, one line naming the flag, and no file at all.
TEST(Sequence, BadRangesPatternsAndFlagsAreClearErrors) {
  TempDir dir;
  write_file(dir / "clock.glsl", kClock);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--frames", "9..3", "-o", "b_%d.png"}, "--frames"},
      {{"--frames", "-2..3", "-o", "b_%d.png"}, "--frames"},
      {{"--frames", "0..3", "-o", "b.png"}, "no frame field"},
      {{"--frames", "0..3", "-o", "b_%d_%d.png"}, "more than one"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--fps", "0"}, "--fps"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--fps", "-24"}, "--fps"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--fps", "nan"}, "--fps"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--time", "1"}, "--time"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--shard", "3/3"}, "--shard"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--shard-mode", "random"}, "--shard-mode"},
      {{"--frames", "0..3", "-o", "b_%d.png", "--shard", "0/2", "--video", "v.mp4"}, "--video"},
      {{"--fps", "24", "-o", "b_%d.png"}, "--frames"},
      {{"--frames", "0..3", "-o", "clock.glsl/b_%d.png"}, "output directory is not a directory"},
  };
  for (const auto& [flags, needle] : cases) {
    std::vector<std::string> args = {"render", "clock.glsl", "--size", "2x2"};
    args.insert(args.end(), flags.begin(), flags.end());
    RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << flags[1] << ": " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_EQ(count_lines_with(r.err, "\n"), 1) << "one line: " << r.err;
    EXPECT_EQ(dir.entries().size(), 1u) << "nothing but clock.glsl after " << r.err;
  }
}

// PATH is what run_marchstudio's shell passes on; restored after the test.
std::string current_path() { return std::getenv("PATH") ? std::getenv("PATH") : ""; }

struct PathGuard {
  std::string old = current_path();
  explicit PathGuard(const std::string& path) { setenv("PATH", path.c_str(), 1); }
  ~PathGuard() { setenv("PATH", old.c_str(), 1); }
};

TEST(Sequence, VideoWithoutFfmpegFailsBeforeRendering) {
  TempDir dir, empty;
  write_file(dir / "clock.glsl", kClock);
  PathGuard path(empty.path().string());
  RunResult r = run_marchstudio({"render", "clock.glsl", "--frames", "0..3", "--size", "2x2", "-o", "v_%d.png",
                                 "--video", "v.mp4"},
                                dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("ffmpeg is not installed"), std::string::npos) << r.err;
  EXPECT_EQ(dir.entries().size(), 1u) << "no frame rendered";
}

// A stand-in ffmpeg records its arguments and writes the output file, so
// the invocation is checked where ffmpeg itself is absent.
TEST(Sequence, VideoRunsFfmpegOnTheFrames) {
  TempDir dir, bin;
  write_file(dir / "clock.glsl", kClock);
  write_file(bin / "ffmpeg", "#!/bin/sh\nprintf '%s\\n' \"$@\" > \"$FAKE_FFMPEG_ARGS\"\n"
                             "for last; do :; done\necho video > \"${last#file:}\"\n");
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  PathGuard path(bin.path().string() + ":" + current_path());
  setenv("FAKE_FFMPEG_ARGS", (bin / "args").c_str(), 1);
  RunResult r = run_marchstudio({"render", "clock.glsl", "--frames", "2..5", "--fps", "12", "--size", "2x2", "-o",
                                 "v_%03d.png", "--video", "out.mp4"},
                                dir.path());
  unsetenv("FAKE_FFMPEG_ARGS");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir / "out.mp4"), "video\n");
  const std::string args = read_file(bin / "args");
  // Every path an absolute file: URL, only files readable (io/video.h).
  const std::string pattern = "file:" + (fs::canonical(dir.path()) / "v_%03d.png").string();
  EXPECT_NE(args.find("-framerate\n12\n-start_number\n2\n-i\n" + pattern + "\n"), std::string::npos) << args;
  EXPECT_NE(args.find("-protocol_whitelist\nfile\n"), std::string::npos) << args;
  EXPECT_EQ(count_files(dir.path(), "v_"), 4);
  EXPECT_EQ(temp_files(dir.path()), std::vector<std::string>{});
}

}  // namespace
}  // namespace ms::test
