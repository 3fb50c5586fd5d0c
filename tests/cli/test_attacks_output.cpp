// Attacks on the output side, through the real binary: a full disk (a file
// size limit everywhere, a small tmpfs where we may mount one), ffmpeg
// under --timeout and SIGTERM, long output names, absurd timeouts and
// window sizes. Before the fix PNG exited 0 over a 0-byte file and JPEG
// exited 1 through libjpeg, leaving its temporary.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// Noise: no format compresses it much, so a frame's size is known roughly.
const char* kMain =
    "float h(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }\n"
    "void mainImage(out vec4 c, in vec2 f) { c = vec4(h(f), h(f + 17.0), h(f + 31.0), 1.0); }\n";

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// What a failed write must leave in `dir`: nothing but `keep`.
void expect_only(const TempDir& dir, std::vector<std::string> keep) {
  std::vector<std::string> e = dir.entries();
  std::sort(e.begin(), e.end());
  std::sort(keep.begin(), keep.end());
  EXPECT_EQ(e, keep);
}

TEST(FullDisk, EveryFormatFailsWithExitThreeAndLeavesNothing) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  // A 16 KiB file size limit (sh counts 512-byte blocks) fails the writes
  // as a full disk does; 320x180 of noise is larger than that in any format.
  for (const char* out : {"o.png", "o.jpg", "o.tif", "o.exr"}) {
    const RunResult r =
        run_marchstudio({"render", "m.glsl", "--size", "320x180", "-o", out}, dir.path(), "ulimit -f 32; ");
    EXPECT_EQ(r.exit_code, 3) << out << ": " << r.err;
    EXPECT_NE(r.err.find(std::string(out) + ": cannot write the file"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;  // no path printed for a file never written
    expect_only(dir, {"m.glsl"});
  }
}

TEST(FullDisk, ASequenceReportsOnlyTheFramesItWrote) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to mount a small tmpfs (the file-size-limit test runs anyway)";
  TempDir dir;
  const fs::path mnt = dir / "disk";
  fs::create_directory(mnt);
  if (::mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=256k") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
  write_file(dir / "m.glsl", kMain);
  const RunResult r = run_marchstudio(
      {"render", "m.glsl", "--size", "160x90", "--frames", "0..39", "-o", (mnt / "f_%02d.png").string()}, dir.path());
  // Every path on stdout is a complete frame; nothing else is on the disk.
  std::vector<std::string> listed;
  for (size_t at = 0; at < r.out.size();) {
    const size_t nl = r.out.find('\n', at);
    listed.push_back(r.out.substr(at, nl - at));
    at = nl + 1;
  }
  std::vector<std::string> on_disk;
  for (const auto& e : fs::directory_iterator(mnt)) on_disk.push_back(e.path().string());
  ::umount(mnt.c_str());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_GT(listed.size(), 0u);
  EXPECT_LT(listed.size(), 40u);
  std::sort(listed.begin(), listed.end());
  std::sort(on_disk.begin(), on_disk.end());
  EXPECT_EQ(listed, on_disk);  // no temporaries, no empty or cut frames
}

// A stand-in for ffmpeg that never finishes: it writes part of its output
// and its pid, then sleeps.
fs::path hanging_ffmpeg(const TempDir& dir) {
  const fs::path bin = dir / "bin";
  // Paths come as file: URLs (io/video.h): the output is the last argument without "file:".
  write_file(bin / "ffmpeg", "#!/bin/sh\nfor last; do :; done\necho partial > \"${last#file:}\"\necho $$ > \"" +
                                 (dir / "ffmpeg.pid").string() + "\"\nexec sleep 300\n");
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  return bin;
}

bool alive(const fs::path& pid_file) {
  const std::string s = read_file(pid_file);
  return !s.empty() && ::kill(std::stoi(s), 0) == 0;
}

TEST(Video, TheTimeoutBoundsFfmpegAndCleansUp) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const fs::path bin = hanging_ffmpeg(dir);
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_marchstudio({"render", "m.glsl", "--size", "32x18", "--frames", "0..1", "-o", "f_%d.png",
                                       "--video", "v.mp4", "--timeout", "3"},
                                      dir.path(), "PATH='" + bin.string() + ":/usr/bin:/bin' ");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("encoding the video did not finish within 3 s"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 30.0);
  EXPECT_FALSE(alive(dir / "ffmpeg.pid"));
  expect_only(dir, {"bin", "f_0.png", "f_1.png", "ffmpeg.pid", "m.glsl"});
}

TEST(Video, SigtermWhileEncodingEndsFfmpegAndRemovesItsTemporary) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const fs::path bin = hanging_ffmpeg(dir);
  // A temporary of a killed earlier encode (pid 1 is never ours): removed.
  write_file(dir / ".v.tmp999999999.mp4", "stale");
  const std::string old_path = std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin";
  ::setenv("PATH", (bin.string() + ":" + old_path).c_str(), 1);  // the child finds the stand-in first
  BackgroundProcess p({MARCH_BIN, "render", "m.glsl", "--size", "32x18", "--frames", "0..1", "-o", "f_%d.png",
                       "--video", "v.mp4"},
                      dir / "out.txt", dir / "err.txt", dir.path());
  ::setenv("PATH", old_path.c_str(), 1);
  ASSERT_TRUE(wait_until([&] { return alive(dir / "ffmpeg.pid"); }, 30)) << read_file(dir / "err.txt");
  p.signal(SIGTERM);
  EXPECT_EQ(p.wait_exit(20), 128 + SIGTERM) << read_file(dir / "err.txt");
  EXPECT_FALSE(alive(dir / "ffmpeg.pid"));
  EXPECT_NE(read_file(dir / "err.txt").find("removed ./.v.tmp999999999.mp4"), std::string::npos)
      << read_file(dir / "err.txt");
  expect_only(dir, {"bin", "err.txt", "f_0.png", "f_1.png", "ffmpeg.pid", "m.glsl", "out.txt"});
}

TEST(OutputNames, LongNamesWorkAndTooLongOnesFailBeforeTheWork) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const std::string ok = std::string(249, 'n') + ".png";  // 253 bytes: legal, its temporary too
  RunResult r = run_marchstudio({"render", "m.glsl", "--size", "8x8", "-o", ok}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / ok));
  const std::string bad = std::string(296, 'n') + ".png";
  const auto t0 = std::chrono::steady_clock::now();
  r = run_marchstudio({"render", "m.glsl", "--size", "8x8", "-o", bad}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("output file name is 300 bytes, more than this file system's 255"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 10.0);
}

TEST(Absurd, AHugeTimeoutIsNoLimitAndAHugeWindowIsRefused) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const RunResult r = run_marchstudio({"render", "m.glsl", "--size", "8x8", "-o", "t.png", "--timeout", "1e10"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Refused before any window: no X server needed.
  const RunResult v = run_marchstudio({"view", "m.glsl", "--size", "100000x100000", "--exit-after", "1"}, dir.path());
  EXPECT_EQ(v.exit_code, 2) << v.err;
  EXPECT_NE(v.err.find("--size: window size 100000x100000 exceeds 16384x16384"), std::string::npos) << v.err;
  EXPECT_EQ(std::count(v.err.begin(), v.err.end(), '\n'), 1) << v.err;
}

}  // namespace
}  // namespace ms::test
