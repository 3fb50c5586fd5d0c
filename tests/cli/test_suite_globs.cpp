// A suite's globs are resolved against the suite's own folder however the
// suite is named: `test glob.toml` and `test ./glob.toml` from that folder
// find the same files as `test ci/glob.toml` from its parent.
#include <gtest/gtest.h>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const fs::path kRipple = source_dir() / "docs/examples/glslviewer/ripple.frag";

// ci/ holding two shaders and a suite whose only case is a glob over them.
struct GlobSuite {
  TempDir dir;
  fs::path ci = dir / "ci";
  GlobSuite() {
    for (const char* f : {"a.frag", "b.frag"}) write_file(ci / f, read_file(kRipple));
    write_file(ci / "glob.toml",
               "[[case]]\nname = \"{name}\"\nshader = \"*.frag\"\nreference = \"refs/{name}.png\"\nsize = [8, 8]\n");
  }
};

TEST(SuiteGlobs, ListFromTheSuitesFolderWithEitherSpelling) {
  GlobSuite s;
  for (const std::string& spelling : {"glob.toml", "./glob.toml"}) {
    const RunResult r = run_marchstudio({"test", "--list", spelling}, s.ci);
    EXPECT_EQ(r.exit_code, 0) << spelling << ": " << r.err;
    EXPECT_EQ(r.err.find("no file matches"), std::string::npos) << spelling << ": " << r.err;
    EXPECT_EQ(count_of(r.out, "\n"), 2) << spelling << ": " << r.out;
    EXPECT_NE(r.out.find("a\ta.frag\t"), std::string::npos) << spelling << ": " << r.out;
    EXPECT_NE(r.out.find("b\tb.frag\t"), std::string::npos) << spelling << ": " << r.out;
  }
  // From the parent, as before: the same two cases under ci/.
  const RunResult parent = run_marchstudio({"test", "--list", "ci/glob.toml"}, s.dir.path());
  EXPECT_EQ(parent.exit_code, 0) << parent.err;
  EXPECT_NE(parent.out.find("a\tci/a.frag\t"), std::string::npos) << parent.out;
}

TEST(SuiteGlobs, RunFromTheSuitesFolder) {
  GlobSuite s;
  RunResult r = run_marchstudio({"test", "./glob.toml", "--update", "--force"}, s.ci);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(s.ci / "refs/a.png"));
  EXPECT_TRUE(fs::exists(s.ci / "refs/b.png"));
  r = run_marchstudio({"test", "glob.toml"}, s.ci);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace ms::test
