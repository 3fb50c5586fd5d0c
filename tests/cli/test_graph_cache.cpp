// A long pruning pass's grid is kept in the cache directory and read back
// (docs/scene-graph.md#pruning): the second render of a graph says so and
// draws the same image; a changed graph misses; a broken entry is a miss,
// not an error; bench stays cold.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "run.h"

namespace ms::test {
namespace {

// Every pass kept (MARCH_PRUNE_CACHE_MS=0), so a small graph shows what a
// large one does, in milliseconds instead of seconds.
std::string env(const TempDir& dir) {
  return "export XDG_CACHE_HOME='" + (dir / "cache").string() + "' MARCH_PRUNE_CACHE_MS=0; ";
}

RunResult render_graph(const TempDir& dir, const std::filesystem::path& scene, const std::string& out) {
  return run_marchstudio({"render", scene.string(), "--size", "96x54", "-o", (dir / out).string(), "-v",
                          "--graph-eval", "interpreter"},
                         dir.path(), env(dir));
}

const std::filesystem::path kPart = source_dir() / "tests/data/graph/part.toml";

int entries(const TempDir& dir) { return count_files(dir / "cache/marchstudio/pruned", ""); }

TEST(PrunedCache, ASecondRenderReadsTheGridAndDrawsTheSameImage) {
  TempDir dir;
  const RunResult a = render_graph(dir, kPart, "a.png");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_NE(a.err.find(", pruning "), std::string::npos) << a.err;
  ASSERT_EQ(entries(dir), 1);
  const RunResult b = render_graph(dir, kPart, "b.png");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.err.find("pruned grid read from the cache"), std::string::npos) << b.err;
  EXPECT_EQ(read_file(dir / "a.png"), read_file(dir / "b.png"));

  // A broken entry (cut short) is a miss: the pass runs, the image is the same.
  for (const auto& e : std::filesystem::directory_iterator(dir / "cache/marchstudio/pruned"))
    std::filesystem::resize_file(e.path(), 100);
  const RunResult c = render_graph(dir, kPart, "c.png");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(c.err.find(", pruning "), std::string::npos) << c.err;
  EXPECT_EQ(read_file(dir / "a.png"), read_file(dir / "c.png"));

  // bench times the pass itself.
  const RunResult d = run_marchstudio(
      {"bench", kPart.string(), "--size", "16x9", "--frames", "1", "--warmup", "0", "--graph-eval", "interpreter", "-v"},
      dir.path(), env(dir));
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_EQ(d.out.find("read from the cache"), std::string::npos) << d.out;
  EXPECT_NE(d.out.find("pruning "), std::string::npos) << d.out;
}

TEST(PrunedCache, AnotherGraphMisses) {
  TempDir dir;
  ASSERT_EQ(render_graph(dir, kPart, "a.png").exit_code, 0);
  // The same part with its sphere's radius changed: another key.
  std::string json = read_file(source_dir() / "tests/data/graph/part.json");
  json.replace(json.find("\"r\": 0.35"), 9, "\"r\": 0.36");
  write_file(dir / "part.json", json);
  write_file(dir / "part.toml", read_file(kPart));
  const RunResult b = render_graph(dir, dir / "part.toml", "b.png");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.err.find(", pruning "), std::string::npos) << b.err;
  EXPECT_EQ(entries(dir), 2);
}

}  // namespace
}  // namespace ms::test
