// Limits that keep hostile input from crashing or losing changes
// (docs/reliability.md): the TOML key-depth guard in front of toml++, and
// live/watcher.h when inotify's queue overflows (a save storm while the
// viewer is busy compiling): an overflow counts as "every watched file
// changed", so the last save is never lost.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "core/error.h"
#include "live/watcher.h"
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
  std::string tmpl = (fs::temp_directory_path() / "marchoverflow-XXXXXX").string();
  ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
  const fs::path dir = tmpl;
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
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ms::live
