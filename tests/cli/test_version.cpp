// The version has one home, CMake's project(VERSION), generated into
// core/version.h: --version prints it and a written image's Software tag
// starts with it.
#include <gtest/gtest.h>

#include <string>

#include "core/version.h"
#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

TEST(Version, VersionFlagPrintsTheProjectVersion) {
  const RunResult r = run_marchstudio({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The user-visible contract, written out: a version bump changes this line too.
  EXPECT_EQ(r.out, "marchstudio 0.1.0\n");
  EXPECT_EQ(r.out, std::string(kSoftware) + "\n");
  EXPECT_EQ(std::string(kSoftware), std::string("marchstudio ") + kVersion);
}

TEST(Version, AStillsSoftwareTagIsTheGeneratedVersion) {
  TempDir dir;
  const RunResult r = run_marchstudio(
      {"render", (source_dir() / "scenes/seed.toml").string(), "--size", "32x18", "-o", (dir / "seed.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string software = "(absent)";
  for (const auto& [k, v] : read_image_info(dir / "seed.png").attributes)
    if (k == "Software") software = v;
  EXPECT_EQ(software, kSoftware);
}

}  // namespace
}  // namespace ms::test
