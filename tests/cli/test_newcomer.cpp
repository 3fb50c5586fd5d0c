// What a new user meets first: `marchstudio help [COMMAND]`, a did-you-mean
// that names the right keys rather than a wrong one (`render.size` is
// neither 'time' nor a light's size), a sequence's per-frame log with a real time in it, and the CI
// guard of `test --update` with CI set but empty.
#include <gtest/gtest.h>

#include <regex>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

TEST(Newcomer, HelpIsASubcommand) {
  RunResult r = run_marchstudio({"help"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("render"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("view"), std::string::npos) << r.out;
  EXPECT_EQ(r.out, run_marchstudio({"--help"}).out);
  r = run_marchstudio({"help", "render"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("--output-dir"), std::string::npos) << r.out;
  EXPECT_EQ(r.out, run_marchstudio({"render", "--help"}).out);
  r = run_marchstudio({"help", "rendr"});
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("did you mean 'render'?"), std::string::npos) << r.err;
}

TEST(Newcomer, SetRenderSizeSuggestsNoUnrelatedKey) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--set",
                                       "render.size=320", "-o", (dir / "a.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown key 'render.size'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("'time'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("[[lights]]"), std::string::npos) << "a light's size is not the image's: " << r.err;
  EXPECT_NE(r.err.find("width and height"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST(Newcomer, ASequenceLogsEachFramesRealTime) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--frames", "0..2",
                                       "--size", "64x36", "-o", (dir / "f_%02d.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex line(R"(frame (\d+) rendered in ([0-9.]+) (m?s))");
  int frames = 0;
  for (std::sregex_iterator it(r.err.begin(), r.err.end(), line), end; it != end; ++it) {
    ++frames;
    // Under a second in milliseconds, whatever the device: never "0.000 s".
    EXPECT_GT(std::stod((*it)[2].str()), 0.0) << "frame " << (*it)[1] << " took no time: " << r.err;
    if ((*it)[3] == "s") EXPECT_GE(std::stod((*it)[2].str()), 1.0) << (*it)[0];
  }
  EXPECT_EQ(frames, 3) << r.err;
}

TEST(Newcomer, AnEmptyCiStillBlocksUpdate) {
  TempDir dir;
  for (const char* f : {"seed.toml", "seed.glsl"}) write_file(dir / f, read_file(source_dir() / "scenes" / f));
  write_file(dir / "suite.toml",
             "[[case]]\nname = \"seed\"\nscene = \"seed.toml\"\nreference = \"refs/seed.png\"\nsize = [32, 18]\n");
  RunResult r = run_marchstudio({"test", (dir / "suite.toml").string(), "--update"}, {}, "CI= ");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("refusing to write references with CI set"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "refs"));
  // CI=false is the documented way to say "not CI".
  r = run_marchstudio({"test", (dir / "suite.toml").string(), "--update"}, {}, "CI=false ");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(dir / "refs" / "seed.png"));
}

}  // namespace
}  // namespace ms::test
