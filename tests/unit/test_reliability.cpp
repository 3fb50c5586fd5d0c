// Limits that keep hostile input from crashing, hanging or losing changes
// (docs/reliability.md): tiles and the memory budget, the --timeout
// deadline and its watchdog, the TOML key-depth guard in front of toml++, and
// live/watcher.h when inotify's queue overflows (a save storm while the
// viewer is busy compiling): an overflow counts as "every watched file
// changed", so the last save is never lost.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <thread>
#include <tuple>

#include "core/deadline.h"
#include "core/error.h"
#include "files.h"
#include "live/watcher.h"
#include "render/tiles.h"
#include "scene/load.h"
#include "scene/toml_guard.h"

namespace ms::live {
namespace {
namespace fs = std::filesystem;

std::string dotted(int n, const std::string& part = "a") {
  std::string s = part;
  for (int i = 1; i < n; ++i) s += "." + part;
  return s;
}

TEST(Tiles, CoverTheFrameExactlyWithNoTileOverTheLimit) {
  for (const auto& [w, h, side] : {std::tuple{1100, 620, 512}, {1, 1, 512}, {512, 512, 512}, {513, 2000, 512},
                                   {16384, 3, 512}, {640, 360, 0}, {97, 61, 10}}) {
    const std::vector<Tile> tiles = split_tiles(w, h, side);
    long long area = 0;
    for (const Tile& t : tiles) {
      EXPECT_GE(t.x, 0);
      EXPECT_GE(t.y, 0);
      EXPECT_LE(t.x + t.width, w);
      EXPECT_LE(t.y + t.height, h);
      if (side > 0) {
        EXPECT_LE(t.width, side);
        EXPECT_LE(t.height, side);
      }
      EXPECT_GT(t.width, 0);
      EXPECT_GT(t.height, 0);
      area += static_cast<long long>(t.width) * t.height;
    }
    EXPECT_EQ(area, static_cast<long long>(w) * h) << w << "x" << h << " in tiles of " << side;  // no overlap, no gap
  }
  EXPECT_EQ(split_tiles(1100, 620).size(), 6u);  // 3 x 2, not 3 x 2 with slivers
  EXPECT_EQ(split_tiles(1100, 620)[0].width, 366);
  EXPECT_EQ(split_tiles(640, 360, 0).size(), 1u);
}

TEST(MemoryBudget, FiguresAndRefusal) {
  const FrameMemory small = frame_memory(640, 360, 2, false);
  EXPECT_DOUBLE_EQ(small.gpu_bytes, 16.0 * 2 * 640 * 360);
  EXPECT_NO_THROW(check_frame_memory(small, 640, 360));
  // Queued frames multiply the host copies, not the GPU buffers.
  const FrameMemory queued = frame_memory(640, 360, 2, false, 6);
  EXPECT_DOUBLE_EQ(queued.gpu_bytes, small.gpu_bytes);
  EXPECT_DOUBLE_EQ(queued.host_bytes, 6 * small.host_bytes);
  try {
    check_frame_memory(frame_memory(16384, 16384, 6, true), 16384, 16384);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_EQ(e.info().key, "--size");
    EXPECT_NE(e.info().what.find("24.0 GiB of GPU buffers"), std::string::npos) << e.what();
  }
}

TEST(Deadline, UnlimitedLimitedAndTheTimeoutError) {
  EXPECT_FALSE(Deadline().limited());
  EXPECT_FALSE(Deadline::after(0).limited());
  EXPECT_FALSE(Deadline::after(-1).limited());
  EXPECT_NO_THROW(Deadline::after(0).check("x"));
  const Deadline d = Deadline::after(0.01);
  EXPECT_TRUE(d.limited());
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_TRUE(d.expired());
  try {
    d.check("the render");
    FAIL() << "no throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::system);
    EXPECT_EQ(std::string(e.what()).rfind("--timeout: the render did not finish within 0.01 s", 0), 0u) << e.what();
  }
}

TEST(Watchdog, DisarmedInTimeItStaysQuiet) {
  Watchdog w(0.05);
  w.arm(Deadline::after(0.05), "quick work");
  w.disarm();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  SUCCEED();  // still here
}

TEST(WatchdogDeathTest, AStuckStepEndsTheProcessWithExit3AndOneLine) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        Watchdog w(0.05);
        w.arm(Deadline::after(0.1), "the render", [] { std::fputs("writer drained\n", stderr); });
        std::this_thread::sleep_for(std::chrono::seconds(5));  // a draw that never returns
      },
      ::testing::ExitedWithCode(3), "writer drained\nmarchstudio: --timeout: the render did not finish within 0.1 s");
}

TEST(TomlGuard, DeepDottedKeysAreRefusedAtTheirLine) {
  for (const std::string& text : {"# x\n\n[" + dotted(100000) + "]\n", "# x\n\n" + dotted(100000) + " = 1\n",
                                  "# x\n\nt = { " + dotted(65) + " = 1 }\n"}) {
    try {
      check_toml_key_depth(text, "s.toml");
      ADD_FAILURE() << "accepted " << text.substr(0, 40);
    } catch (const Error& e) {
      EXPECT_EQ(e.info().line, 3);
      EXPECT_NE(std::string(e.what()).find("nested more than 64 levels"), std::string::npos) << e.what();
    }
  }
  // Through the loader, which would otherwise crash in toml++.
  EXPECT_THROW(parse_scene("[" + dotted(100000) + "]\n", "s.toml"), Error);
}

TEST(TomlGuard, DotsInValuesStringsAndCommentsAreFine) {
  const std::string many_dots(500, '.');
  EXPECT_NO_THROW(check_toml_key_depth("a.b.c = 1.5\n"
                                       "keys = [[0.0, 1.5, 2.5, 3.5], [1.0, 1.5, 2.5, 3.5]]\n"
                                       "s = \"" + many_dots + "\"\n"
                                       "l = '" + many_dots + "'\n"
                                       "m = \"\"\"\n" + many_dots + "\n\\\"" + many_dots + "\"\"\"\n"
                                       "n =  + many_dots + \n"
                                       "# " + many_dots + "\n"
                                       "t = 1979-05-27T07:32:00.999\n"
                                       "[" + dotted(64) + "]\n",
                                       "s.toml"));
}

TEST(WatcherOverflow, AnOverflowReportsEveryWatchedFile) {
  const test::TempDir tmp;
  const fs::path& dir = tmp.path();
  std::ofstream(dir / "map.glsl") << "x";
  std::ofstream(dir / "scene.toml") << "x";
  Watcher w;
  w.watch({dir / "map.glsl", dir / "scene.toml"});
  // Touching two files in turn queues IN_ATTRIB events that inotify cannot
  // merge. Pass the kernel's queue limit (fs.inotify.max_queued_events,
  // 16384 by default) with files nobody watches by name, so only the
  // overflow can report the watched ones.
  long limit = 16384;
  if (std::ifstream in("/proc/sys/fs/inotify/max_queued_events"); in) in >> limit;
  if (limit > 1000000) GTEST_SKIP() << "max_queued_events is " << limit;
  std::ofstream(dir / "noise0.txt") << "n";
  std::ofstream(dir / "noise1.txt") << "n";
  for (long i = 0; i <= limit + 1; ++i)
    ASSERT_EQ(::utimensat(AT_FDCWD, (dir / ("noise" + std::to_string(i % 2) + ".txt")).c_str(), nullptr, 0), 0);
  const std::vector<fs::path> changed = w.poll();
  const std::vector<fs::path> want = {dir / "map.glsl", dir / "scene.toml"};
  EXPECT_EQ(changed, want);
}

}  // namespace
}  // namespace ms::live
