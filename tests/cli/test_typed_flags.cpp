// Flags are typed where they are read: --help lists an enum flag's
// choices, a bad value is refused before any input is loaded, and a --jobs
// line's value goes through the same parser as the flag.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

TEST(TypedFlags, HelpListsTheChoices) {
  for (const std::string cmd : {"render", "bench", "sweep", "view"}) {
    const RunResult r = run_marchstudio({cmd, "--help"});
    ASSERT_EQ(r.exit_code, 0) << cmd << ": " << r.err;
    EXPECT_NE(r.out.find("--dispatch TEXT:{fragment, compute, auto}"), std::string::npos) << cmd << ": " << r.out;
  }
  // `test` refuses auto (a suite checks one dispatch), so its help offers two.
  const RunResult t = run_marchstudio({"test", "--help"});
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("--dispatch TEXT:{fragment, compute}"), std::string::npos) << t.out;
  for (const std::string cmd : {"test", "compare"}) {
    const RunResult r = run_marchstudio({cmd, "--help"});
    EXPECT_NE(r.out.find("--exit-codes TEXT:{default, idiff}"), std::string::npos) << cmd << ": " << r.out;
  }
  const RunResult c = run_marchstudio({"compare", "--help"});
  EXPECT_NE(c.out.find("--metric TEXT:{psnr, mae, max, fraction, flip}"), std::string::npos) << c.out;
}

// Parsed at the edge: a bad value is the error although the input does not
// exist, which loading would have reported first.
TEST(TypedFlags, ABadValueIsRefusedBeforeTheInputIsRead) {
  TempDir dir;
  const std::string missing = (dir / "missing.toml").string();
  const std::vector<std::vector<std::string>> cases = {
      {"render", missing, "--frames", "0..3", "--size", "0x9", "-o", (dir / "f_%d.png").string()},
      {"render", missing, "--frames", "0..3", "--dispatch", "gpu", "-o", (dir / "f_%d.png").string()},
      {"render", missing, "--frames", "0..3", "--compute-group", "64x64", "-o", (dir / "f_%d.png").string()},
      {"bench", missing, "--size", "9"},
      {"sweep", missing, "--dispatch", "gpu"},
      {"render", missing, "--format", "jpeg", "--output-dir", (dir / "out").string()},
      {"view", missing, "--shader-dir", (dir / "none").string(), "--drag", "materials[0].color=1,0,0@9..3"},
  };
  const std::vector<std::string> flags = {"--size", "--dispatch", "--compute-group", "--size",
                                          "--dispatch", "--format", "invalid --drag"};
  for (size_t i = 0; i < cases.size(); ++i) {
    const RunResult r = run_marchstudio(cases[i]);
    EXPECT_EQ(r.exit_code, 2) << cases[i][3] << ": " << r.err;
    EXPECT_EQ(r.err.rfind("marchstudio: " + flags[i], 0), 0u) << r.err;
    EXPECT_EQ(r.err.find("missing.toml"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_TRUE(dir.entries().empty());
}

// Under --exit-codes idiff a bad value is "could not run" (4), as it was
// when the value was parsed after the flags; either order of the two flags.
TEST(TypedFlags, IdiffCodesStillCoverABadValue) {
  TempDir dir;
  const std::string suite = (dir / "missing.toml").string();
  const RunResult a = run_marchstudio({"test", suite, "--dispatch", "gpu", "--exit-codes", "idiff"});
  EXPECT_EQ(a.exit_code, 4) << a.err;
  EXPECT_NE(a.err.find("--dispatch 'gpu'"), std::string::npos) << a.err;
  EXPECT_EQ(run_marchstudio({"test", suite, "--exit-codes", "idiff", "--dispatch", "gpu"}).exit_code, 4);
  EXPECT_EQ(run_marchstudio({"test", suite, "--dispatch", "gpu"}).exit_code, 2);
  EXPECT_EQ(run_marchstudio({"test", suite, "--exit-codes", "oiio"}).exit_code, 2);
}

// A --jobs line's missing-media is checked as the flag is (it was once
// taken as given, and an unknown name did nothing).
TEST(TypedFlags, AJobsMissingMediaIsOneOfTheNames) {
  TempDir dir;
  write_file(dir / "t.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(p.x / iResolution.x, 0, 0, 1); }\n");
  const std::string job = "{\"scene\": \"t.glsl\", \"output\": \"x.png\", \"size\": \"8x8\"";
  write_file(dir / "jobs.jsonl", job + ", \"missing-media\": \"grey\"}\n");
  const RunResult r = run_marchstudio({"render", "--jobs", (dir / "jobs.jsonl").string()}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("jobs.jsonl:1: --missing-media: 'grey' is not one of error, noise, black"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  write_file(dir / "jobs.jsonl", job + ", \"missing-media\": \"black\"}\n");
  const RunResult ok = run_marchstudio({"render", "--jobs", (dir / "jobs.jsonl").string()}, dir.path());
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace ms::test
