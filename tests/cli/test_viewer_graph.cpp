// The viewer on an interpreted scene graph (docs/viewer.md#graphs), under
// Xvfb: a saved move of a node updates the node buffers and the pruning
// with no compile, and the frame is render's of the moved graph; a new
// node recompiles once, on the worker; a drag's rebuilds keep the buffers.
// Frames are counted, never timed.
#include <gtest/gtest.h>

#include <regex>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

class ViewerGraph : public ::testing::Test {
 protected:
  // The viewer on a copy of tests/data/graph/<name>.toml and .json.
  void start(const std::string& name, const std::vector<std::string>& flags) {
    if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
    name_ = name;
    const fs::path data = fs::path(MARCH_TEST_DATA) / "graph";
    write_file(dir / (name + ".toml"), read_file(data / (name + ".toml")));
    json_ = read_file(data / (name + ".json"));
    write_file(dir / (name + ".json"), json_);
    std::vector<std::string> argv = {"env", x_display(), MARCH_BIN, "view",
                                     (dir / (name + ".toml")).string(), "--size", "160x90", "--paused", "--no-panel",
                                     "--log", log().string(), "--capture-dir", (dir / "cap").string(),
                                     "--exit-after", "200"};
    argv.insert(argv.end(), flags.begin(), flags.end());
    proc = std::make_unique<BackgroundProcess>(argv, dir / "out.txt", dir / "err.txt");
    ASSERT_TRUE(proc->started());
    ASSERT_FALSE(wait_for_line(log(), "^reload ok 0 ", 120).empty()) << read_file(log()) << read_file(dir / "err.txt");
    ASSERT_FALSE(wait_for_line(log(), "^capture 0 ", 10).empty());
  }
  // Save the graph with `from` replaced by `to`; wait for reload k and its capture.
  std::string save(const std::string& from, const std::string& to, int k) {
    const size_t at = json_.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) return {};
    json_.replace(at, from.size(), to);
    save_by_rename(dir / (name_ + ".json"), json_);
    const std::string line = wait_for_line(log(), "^reload (ok|failed) " + std::to_string(k) + " ", 120);
    EXPECT_EQ(line.rfind("reload ok ", 0), 0u) << line << read_file(log()) << read_file(dir / "err.txt");
    EXPECT_FALSE(wait_for_line(log(), "^capture " + std::to_string(k) + " ", 10).empty());
    return line;
  }
  // The "graph updated" lines so far, and how often "reload compiling K" was logged.
  std::vector<std::string> graph_lines() const { return matching("^graph updated: "); }
  size_t compiles(int k) const { return matching("^reload compiling " + std::to_string(k) + "$").size(); }
  std::vector<std::string> matching(const std::string& re) const {
    std::vector<std::string> out;
    for (const std::string& l : file_lines(log()))
      if (std::regex_search(l, std::regex(re))) out.push_back(l);
    return out;
  }
  fs::path log() const { return dir / "log.txt"; }
  Image capture(int k) { return read_image(dir / "cap" / ("frame_" + std::to_string(k) + ".png")); }
  // render of the graph as saved now, with `flags`.
  Image render(const std::vector<std::string>& flags) {
    TempDir r;
    write_file(r / (name_ + ".toml"), read_file(dir / (name_ + ".toml")));
    write_file(r / (name_ + ".json"), json_);
    std::vector<std::string> args = {"render", (r / (name_ + ".toml")).string(), "--size", "160x90", "-o",
                                     (r / "out.png").string()};
    args.insert(args.end(), flags.begin(), flags.end());
    const RunResult run = run_marchstudio(args);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return read_image(r / "out.png");
  }

  TempDir dir;
  std::string name_, json_;
  std::unique_ptr<BackgroundProcess> proc;
};

TEST_F(ViewerGraph, AMoveRepointsTheBuffersAndANewNodeCompilesOnce) {
  start("view_edit", {"--graph-eval", "interpreter"});
  ASSERT_EQ(graph_lines().size(), 1u) << read_file(log());
  // The ball moves inside the frame: the same box.
  save("[-0.45, 1, 0]", "[0.45, 1, 0]", 1);
  std::vector<std::string> lines = graph_lines();
  ASSERT_EQ(lines.size(), 2u) << read_file(log());
  EXPECT_TRUE(std::regex_match(lines[1], std::regex(R"(graph updated: 0 programs compiled, pruning \d+\.\d ms)")))
      << lines[1];
  EXPECT_EQ(compiles(1), 0u) << read_file(log());
  EXPECT_GT(mean_abs_diff(capture(1), capture(0)), 1e-3) << "the move did not change the frame";
  EXPECT_LE(max_abs_diff(capture(1), render({"--graph-eval", "interpreter"})), 2.0 / 255.0);
  // The frame moves: a new box, bounds and grid, all in buffers and uniforms.
  save("[0, 1, 0]", "[0.3, 1.2, -0.2]", 2);
  lines = graph_lines();
  ASSERT_EQ(lines.size(), 3u) << read_file(log());
  EXPECT_TRUE(std::regex_match(lines[2], std::regex(R"(graph updated: 0 programs compiled, pruning \d+\.\d ms)")))
      << lines[2];
  EXPECT_EQ(compiles(2), 0u) << read_file(log());
  EXPECT_GT(mean_abs_diff(capture(2), capture(1)), 1e-3) << "the move did not change the frame";
  EXPECT_LE(max_abs_diff(capture(2), render({"--graph-eval", "interpreter"})), 2.0 / 255.0);
  // A third child is a new program: compiled once, on the worker.
  save("\"material\": \"ball\"}", "\"material\": \"ball\"},\n  {\"sdf\": \"sdSphere\", \"r\": 0.3, \"translate\": [0, 0.4, -0.3]}",
       3);
  lines = graph_lines();
  ASSERT_EQ(lines.size(), 4u) << read_file(log());
  EXPECT_TRUE(std::regex_match(lines[3], std::regex(R"(graph updated: [1-9]\d* programs compiled, pruning .* ms)")))
      << lines[3];
  EXPECT_EQ(compiles(3), 1u) << read_file(log());
  EXPECT_LE(max_abs_diff(capture(3), render({"--graph-eval", "interpreter"})), 2.0 / 255.0);
  EXPECT_TRUE(proc->running());
}

// A move that changes the graph's box changes the scene's bounds, which the
// viewer reads from uniforms, and the pruned grid, which lives in the cell
// buffer: still no compile. Traced by compute.
TEST_F(ViewerGraph, AMoveOfTheBoxCompilesNothingUnderCompute) {
  start("view_columns", {"--graph-eval", "interpreter", "--dispatch", "compute"});
  ASSERT_FALSE(matching("^dispatch compute=").empty()) << read_file(log());
  save("[0.6, 0.6, 0]", "[1.1, 0.9, 0.2]", 1);
  const std::vector<std::string> lines = graph_lines();
  ASSERT_EQ(lines.size(), 2u) << read_file(log());
  EXPECT_TRUE(std::regex_match(lines[1], std::regex(R"(graph updated: 0 programs compiled, pruning .* ms)")))
      << lines[1];
  EXPECT_EQ(compiles(1), 0u) << read_file(log());
  EXPECT_GT(mean_abs_diff(capture(1), capture(0)), 1e-3) << "the move did not change the frame";
  EXPECT_LE(max_abs_diff(capture(1), render({"--graph-eval", "interpreter"})), 2.0 / 255.0);
}

// A panel drag rebuilds the program twice (live, then folded) but keeps the
// node buffers and the grid: no new "graph updated" line, and the shot
// after the drag is render's of the final colour.
TEST_F(ViewerGraph, ADragKeepsTheBuffers) {
  start("view_edit", {"--graph-eval", "interpreter", "--shot-dir", (dir / "shots").string(), "--shot-frame", "20",
                      "--drag", "materials[1].color=0.1,0.3,0.9@3..8"});
  ASSERT_FALSE(wait_for_line(log(), "^screenshot ", 120).empty()) << read_file(log()) << read_file(dir / "err.txt");
  EXPECT_EQ(matching("^values ok ").size(), 2u) << read_file(log());
  EXPECT_EQ(graph_lines().size(), 1u) << read_file(log());
  const Image want = render({"--graph-eval", "interpreter", "--set", "materials.ball.color=[0.1,0.3,0.9]"});
  EXPECT_LE(max_abs_diff(read_image(dir / "shots/view_edit_1.png"), want), 2.0 / 255.0);
}

}  // namespace
}  // namespace ms::test
