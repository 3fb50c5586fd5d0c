// A pruned-grid cache entry is a hint, never trusted as it stands
// (render/graph_field_cache.h): one wrong word in the grid changes which
// nodes a pixel evaluates. A damaged, lying, linked or FIFO entry is a
// miss, said once under -v: the image and the mesh are the cold ones, and
// a damaged file is written again.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

const fs::path kPart = source_dir() / "tests/data/graph/part.toml";

// Every pass kept (MARCH_PRUNE_CACHE_MS=0); bounded, so an entry that
// would block the read fails the test instead of hanging it.
std::string env(const TempDir& dir) {
  return "export XDG_CACHE_HOME='" + (dir / "cache").string() + "' MARCH_PRUNE_CACHE_MS=0; timeout 120 ";
}

RunResult render(const TempDir& dir, const std::string& out) {
  return run_marchstudio({"render", kPart.string(), "--size", "96x54", "-o", (dir / out).string(), "-v",
                          "--graph-eval", "interpreter"},
                         dir.path(), env(dir));
}

RunResult mesh(const TempDir& dir, const std::string& out) {
  return run_marchstudio({"mesh", kPart.string(), "--resolution", "32", "-o", (dir / out).string(), "-v",
                          "--graph-eval", "interpreter"},
                         dir.path(), env(dir));
}

std::vector<fs::path> entries(const TempDir& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir / "cache/marchstudio/pruned")) out.push_back(e.path());
  return out;
}

// One bit flipped in every 97th byte past the header's first 128 bytes.
void poison(const fs::path& entry) {
  std::string bytes = read_file(entry);
  for (std::size_t i = 128; i < bytes.size(); i += 97) bytes[i] ^= 0x10;
  write_file(entry, bytes);
}

bool read_back(const RunResult& r) { return r.err.find("pruned grid read from the cache") != std::string::npos; }

TEST(PrunedCacheTrust, BitFlipsThroughTheBodyGiveTheColdImageAndTheEntryIsWrittenAgain) {
  TempDir dir;
  RunResult r = render(dir, "cold.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(entries(dir).size(), 1u);
  const fs::path entry = entries(dir)[0];
  const std::string good = read_file(entry);
  poison(entry);

  r = render(dir, "poisoned.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(read_back(r)) << r.err;
  EXPECT_EQ(count_of(r.err, "differs from what was written"), 1) << r.err;
  EXPECT_EQ(count_of(r.err, "written again"), 1) << r.err;
  EXPECT_TRUE(read_file(dir / "poisoned.png") == read_file(dir / "cold.png"));
  EXPECT_EQ(fs::file_size(entry), good.size()) << "the entry is written again";

  r = render(dir, "warm.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(read_back(r)) << r.err;
  EXPECT_EQ(r.err.find("not used"), std::string::npos) << r.err;
  EXPECT_TRUE(read_file(dir / "warm.png") == read_file(dir / "cold.png"));
}

TEST(PrunedCacheTrust, ACutShortOrLyingOrOldEntryIsAMiss) {
  TempDir dir;
  ASSERT_EQ(render(dir, "cold.png").exit_code, 0);
  const fs::path entry = entries(dir)[0];
  const std::string good = read_file(entry);
  struct Case {
    std::string bytes, needle;
  };
  std::string lying = good, cells = good, old = good;
  lying[40] ^= 0x04;   // the bytes kept of the first buffer: 4 more or fewer than the body holds
  cells[48] ^= 0x01;   // the cells' buffer: not this plan's size
  old[7] = '1';        // the first layout, which had no hash
  const std::vector<Case> cases = {
      {good.substr(0, good.size() / 2), "its header says"},
      {good.substr(0, 60), "not a pruned grid"},
      {lying, "not used"},
      {cells, "does not fit this graph's plan"},
      {old, "not a pruned grid of this version"},
  };
  for (const Case& c : cases) {
    write_file(entry, c.bytes);
    const RunResult r = render(dir, "again.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(read_back(r)) << r.err;
    EXPECT_EQ(count_of(r.err, c.needle), 1) << r.err;
    EXPECT_TRUE(read_file(dir / "again.png") == read_file(dir / "cold.png"));
    EXPECT_EQ(fs::file_size(entry), good.size()) << c.needle << ": written again";
  }
}

TEST(PrunedCacheTrust, ALinkedEntryIsNotFollowedAndAFifoNeverWaits) {
  TempDir dir;
  ASSERT_EQ(render(dir, "cold.png").exit_code, 0);
  const fs::path entry = entries(dir)[0], elsewhere = dir / "elsewhere.bin";
  // A valid entry, but reached through a link: the writer never makes one.
  fs::rename(entry, elsewhere);
  const std::string target = read_file(elsewhere);
  fs::create_symlink(elsewhere, entry);
  RunResult r = render(dir, "link.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(read_back(r)) << r.err;
  EXPECT_EQ(count_of(r.err, "symbolic link, not followed"), 1) << r.err;
  EXPECT_TRUE(read_file(dir / "link.png") == read_file(dir / "cold.png"));
  EXPECT_TRUE(fs::is_symlink(entry)) << "a link is not ours to replace";
  EXPECT_TRUE(read_file(elsewhere) == target) << "nor written through";

  fs::remove(entry);
  ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
  r = render(dir, "fifo.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;  // 124: it waited on the FIFO
  EXPECT_EQ(count_of(r.err, "FIFO"), 1) << r.err;
  EXPECT_TRUE(read_file(dir / "fifo.png") == read_file(dir / "cold.png"));
  EXPECT_TRUE(fs::is_fifo(entry));
}

TEST(PrunedCacheTrust, MeshWithAPoisonedEntryGivesTheColdMesh) {
  TempDir dir;
  RunResult r = mesh(dir, "cold.ply");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_FALSE(entries(dir).empty());
  for (const fs::path& e : entries(dir)) poison(e);
  r = mesh(dir, "poisoned.ply");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(read_back(r)) << r.err;
  EXPECT_EQ(count_of(r.err, "differs from what was written"), 1) << r.err;
  EXPECT_TRUE(read_file(dir / "poisoned.ply") == read_file(dir / "cold.ply"));
}

}  // namespace
}  // namespace ms::test
