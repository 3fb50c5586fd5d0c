// A shader or scene named alone, `marchstudio waves.frag` (glslViewer's
// habit), opens in the viewer as `marchstudio view waves.frag` does. Tested
// without a window: on a display that is not there, both end in the
// viewer's own error, never "unknown subcommand".
#include <gtest/gtest.h>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// No display to open: the viewer fails at once, after the dispatch.
const std::string kNoDisplay = "export DISPLAY=:9999; unset WAYLAND_DISPLAY; ";

TEST(ImplicitView, AShaderAloneIsView) {
  TempDir dir;
  write_file(dir / "waves.frag", read_file(source_dir() / "docs/examples/glslviewer/ripple.frag"));
  const RunResult view = run_marchstudio({"view", "waves.frag"}, dir.path(), kNoDisplay);
  const RunResult alone = run_marchstudio({"waves.frag"}, dir.path(), kNoDisplay);
  ASSERT_NE(view.exit_code, 0) << "a viewer opened on no display: " << view.err;
  EXPECT_EQ(alone.err.find("unknown subcommand"), std::string::npos) << alone.err;
  EXPECT_EQ(alone.exit_code, view.exit_code) << alone.err;
  EXPECT_EQ(alone.err, view.err);
  // The viewer's flags come along.
  const RunResult flags = run_marchstudio({"waves.frag", "--no-such-flag"}, dir.path(), kNoDisplay);
  EXPECT_EQ(flags.exit_code, 2) << flags.err;
  EXPECT_NE(flags.err.find("'--no-such-flag' for 'view'"), std::string::npos) << flags.err;
}

TEST(ImplicitView, ASceneAloneIsView) {
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  const RunResult view = run_marchstudio({"view", seed}, {}, kNoDisplay);
  const RunResult alone = run_marchstudio({seed}, {}, kNoDisplay);
  EXPECT_EQ(alone.exit_code, view.exit_code) << alone.err;
  EXPECT_EQ(alone.err, view.err);
}

TEST(ImplicitView, AMissingFileOrWordIsStillUnknownWithAHint) {
  TempDir dir;
  RunResult r = run_marchstudio({"nosuch.frag"}, dir.path(), kNoDisplay);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err;
  EXPECT_NE(r.err.find("unknown subcommand 'nosuch.frag'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("marchstudio view FILE"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("marchstudio render FILE"), std::string::npos) << r.err;
  r = run_marchstudio({"rendr", "x.toml"}, dir.path(), kNoDisplay);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("did you mean 'render'?"), std::string::npos) << r.err;
  // A directory with a shader's extension is not a file to open.
  fs::create_directory(dir / "dir.frag");
  r = run_marchstudio({"dir.frag"}, dir.path(), kNoDisplay);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown subcommand"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
