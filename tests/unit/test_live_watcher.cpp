// live/watcher.h with real inotify on a temporary directory: in-place
// writes, rename-over saves (vim, VS Code), delete + recreate, filtering by
// name, match-any after a failure, re-targeting the watched set, debounce.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <thread>

#include "live/watcher.h"
#include "files.h"

namespace ms::live {
namespace {
namespace fs = std::filesystem;

class LiveWatcher : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = tmp_dir.path();
    write("a.glsl", "a");
    write("b.glsl", "b");
    fs::create_directories(dir / "sub");
    write("sub/c.glsl", "c");
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
  // What a rename-on-save editor does: write a temporary, rename it over.
  void save_by_rename(const std::string& name, const std::string& text) {
    write(name + ".tmp~", text);
    fs::rename(dir / (name + ".tmp~"), dir / name);
  }
  std::vector<fs::path> wait(Watcher& w) { return w.wait(2000, 20, 200); }
  // For "nothing arrives": inotify delivers within microseconds, 300 ms is ample.
  std::vector<fs::path> wait_none(Watcher& w) { return w.wait(300, 20, 200); }
  test::TempDir tmp_dir;
  fs::path dir;
};

TEST_F(LiveWatcher, InPlaceWriteOfAWatchedFile) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  write("a.glsl", "changed");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "a.glsl"});
}

TEST_F(LiveWatcher, RenameOverIsSeenAndWatchingContinues) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  save_by_rename("a.glsl", "v2");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "a.glsl"});
  // A file watch would now sit on the old, deleted inode; a directory watch does not.
  save_by_rename("a.glsl", "v3");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "a.glsl"});
}

TEST_F(LiveWatcher, DeleteAndRecreate) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  fs::remove(dir / "a.glsl");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "a.glsl"});
  write("a.glsl", "back");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "a.glsl"});
}

TEST_F(LiveWatcher, OtherFilesInTheDirectoryAreFilteredOut) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  write("b.glsl", "not watched");
  write("notes.txt", "x");
  EXPECT_TRUE(wait_none(w).empty());
}

TEST_F(LiveWatcher, MatchAnyAcceptsSourceLikeNamesOnly) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  w.set_match_any(true);
  write("shot.png", "not source");
  EXPECT_TRUE(wait_none(w).empty());
  write("new.glsl", "a new include");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "new.glsl"});
}

TEST_F(LiveWatcher, RewatchingFollowsTheNewSet) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  w.watch({dir / "sub/c.glsl"});  // a.glsl dropped, sub/ added
  EXPECT_EQ(w.files(), std::vector<fs::path>{dir / "sub/c.glsl"});
  write("a.glsl", "dropped");
  EXPECT_TRUE(wait_none(w).empty());
  write("sub/c.glsl", "new");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "sub/c.glsl"});
  EXPECT_EQ(w.directories(), std::vector<fs::path>{dir / "sub"});
}

TEST_F(LiveWatcher, OneSavePerBurst) {
  Watcher w;
  w.watch({dir / "a.glsl", dir / "b.glsl"});
  // An editor writing in several steps, then a second file: one settled batch.
  std::thread writer([&] {
    for (int i = 0; i < 5; ++i) {
      write("a.glsl", "step " + std::to_string(i));
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    write("b.glsl", "too");
  });
  writer.join();
  const std::vector<fs::path> got = wait(w);
  EXPECT_EQ(got, (std::vector<fs::path>{dir / "a.glsl", dir / "b.glsl"}));
  EXPECT_TRUE(w.poll().empty());  // nothing left over for a second reload
}

TEST_F(LiveWatcher, MissingDirectoryIsRetried) {
  Watcher w;
  w.watch({dir / "later/x.glsl"});
  EXPECT_TRUE(w.directories().empty());
  fs::create_directories(dir / "later");
  w.watch({dir / "later/x.glsl"});
  write("later/x.glsl", "now");
  EXPECT_EQ(wait(w), std::vector<fs::path>{dir / "later/x.glsl"});
}

TEST_F(LiveWatcher, TimeoutReturnsEmpty) {
  Watcher w;
  w.watch({dir / "a.glsl"});
  EXPECT_TRUE(w.wait(50, 10, 100).empty());
}

}  // namespace
}  // namespace ms::live
