// --help tells the defaults the binary really uses, the hidden tiling
// flags' errors name the flag and print their limit readably, view --time
// takes the same times as render --time, and usage.md's -o directories.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::string kSeed = (source_dir() / "scenes" / "seed.toml").string();

// The help text of one option: its line and the wrapped lines under it.
std::string help_of(const std::string& help, const std::string& option) {
  const size_t at = help.find("  " + option + " ");
  if (at == std::string::npos) return {};
  size_t end = help.find("\n  -", at + 1);
  return help.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

TEST(HelpDefaults, RenderHelpShowsTheDefaultsItUses) {
  const RunResult r = run_marchstudio({"render", "--help"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(help_of(r.out, "-o,--output").find("<stem>.png"), std::string::npos) << r.out;
  EXPECT_NE(help_of(r.out, "--backend").find("auto (default"), std::string::npos) << r.out;
  EXPECT_NE(help_of(r.out, "--frame").find("default round(time x fps)"), std::string::npos) << r.out;
  // The scene's [render] time wins over 0 when --time is not given.
  const std::string time = help_of(r.out, "--time");
  EXPECT_NE(time.find("the scene's [render] time"), std::string::npos) << time;
  EXPECT_EQ(time.find("(default 0)"), std::string::npos) << time;
}

TEST(HelpDefaults, TileStillErrorsNameTheFlagAndNoHugeNumber) {
  TempDir dir;
  const std::vector<std::vector<std::string>> bad = {
      {"--tile-still"}, {"--tile-still", "-3"}, {"--tile-size", "-1"}, {"--tile-size", "x"}};
  for (const std::vector<std::string>& extra : bad) {
    std::vector<std::string> args = {"render", kSeed, "--size", "32x18", "-o", (dir / "t.png").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 2) << extra[0] << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("marchstudio: " + extra[0], 0), 0u) << r.err;  // named first, not "marchstudio: : "
    EXPECT_EQ(r.err.find("17976931348623157"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
  EXPECT_TRUE(dir.entries().empty());
  const RunResult ok = run_marchstudio(
      {"render", kSeed, "--size", "32x18", "--tile-still", "16", "-o", (dir / "t.png").string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

TEST(HelpDefaults, ViewLimitsPrintReadably) {
  const RunResult r = run_marchstudio({"view", kSeed, "--exit-after", "-1"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--exit-after"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("17976931348623157"), std::string::npos) << r.err;
}

// render --time takes any finite time within a float; view --time too. With
// no display the viewer then stops at its window (exit 3), past the flags.
TEST(HelpDefaults, ViewTimeTakesRenderTimes) {
  TempDir dir;
  const RunResult render = run_marchstudio({"render", kSeed, "--size", "16x9", "--time", "-1", "-o",
                                            (dir / "t.png").string()});
  EXPECT_EQ(render.exit_code, 0) << render.err;
  const std::string no_display = "unset DISPLAY WAYLAND_DISPLAY; ";
  const RunResult view = run_marchstudio({"view", kSeed, "--time", "-1", "--exit-after", "0"}, {}, no_display);
  EXPECT_NE(view.exit_code, 2) << view.err;
  EXPECT_EQ(view.err.find("--time"), std::string::npos) << view.err;
  for (const char* t : {"1e39", "nan"}) {
    const RunResult both[] = {run_marchstudio({"render", kSeed, "--time", t, "-o", (dir / "u.png").string()}),
                              run_marchstudio({"view", kSeed, "--time", t}, {}, no_display)};
    for (const RunResult& r : both) {
      EXPECT_EQ(r.exit_code, 2) << t << ": " << r.err;
      EXPECT_NE(r.err.find("--time"), std::string::npos) << r.err;
    }
  }
}

// docs/usage.md: a missing -o directory is made; one that cannot be made
// (a file in the way) is one line naming -o, exit 2, nothing written.
TEST(DocClaims, AMissingOutputDirectoryIsMade) {
  TempDir dir;
  const fs::path out = dir / "new" / "deeper" / "x.png";
  const RunResult r = run_marchstudio({"render", kSeed, "--size", "16x9", "-o", out.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(out));
  write_file(dir / "afile", "x");
  const RunResult bad =
      run_marchstudio({"render", kSeed, "--size", "16x9", "-o", (dir / "afile" / "sub" / "x.png").string()});
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("afile/sub: -o: output directory cannot be made: "), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace ms::test
