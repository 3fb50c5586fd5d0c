// docs/performance.md#start-up: what a run loads. OpenImageIO (~260
// libraries) and OSMesa (LLVM) are opened only when a run needs them, so
// --version, --help and a PNG or EXR still never load them (nor OpenVDB,
// which only mesh/'s .vdb writer loads, from marchstudio-vdb.so); a TIFF does,
// from the module beside the binary; and a missing module is one line,
// exit 3, no file. Checked with the dynamic loader's own log
// (LD_DEBUG=files), never with a clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "run.h"

namespace ms::test {
namespace {

bool loaded(const RunResult& r, const std::string& soname) {
  return r.err.find("file=" + soname) != std::string::npos;  // "file=libX.so [0];  needed by" or "dynamically loaded by"
}

RunResult run_logged(const std::vector<std::string>& args, const TempDir& dir) {
  return run_marchstudio(args, dir.path(), "LD_DEBUG=files; export LD_DEBUG; ");
}

TEST(StartUp, VersionAndHelpLoadNeitherOpenImageIONorOSMesaNorOpenVDB) {
  TempDir dir;
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--version"}, {"--help"}, {"render", "--help"}}) {
    const RunResult r = run_logged(args, dir);
    ASSERT_EQ(r.exit_code, 0) << args[0] << "\n" << r.err.substr(0, 2000);
    ASSERT_TRUE(loaded(r, "libc.so.6")) << "LD_DEBUG gave no log: " << r.err.substr(0, 500);
    EXPECT_FALSE(loaded(r, "libOpenImageIO.so.2.4")) << args[0];
    EXPECT_FALSE(loaded(r, "libOSMesa.so.8")) << args[0];
    EXPECT_FALSE(loaded(r, "marchstudio-oiio.so")) << args[0];
    EXPECT_FALSE(loaded(r, "libopenvdb.so.10.0")) << args[0];  // only mesh/'s .vdb writer loads it
    EXPECT_FALSE(loaded(r, "marchstudio-vdb.so")) << args[0];
  }
}

TEST(StartUp, APngOrExrStillNeverLoadsOpenImageIO) {
  TempDir dir;
  for (const char* name : {"seed.png", "seed.exr"}) {
    const RunResult r = run_logged({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "64x36", "-o",
                                    (dir / name).string()},
                                   dir);
    ASSERT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
    EXPECT_FALSE(loaded(r, "libOpenImageIO.so.2.4")) << name;
    EXPECT_TRUE(std::filesystem::exists(dir / name));
  }
}

TEST(StartUp, ATiffStillLoadsTheImageModule) {
  TempDir dir;
  const RunResult r = run_logged(
      {"render", (source_dir() / "scenes/seed.toml").string(), "--size", "64x36", "-o", (dir / "seed.tif").string()},
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(loaded(r, "libOpenImageIO.so.2.4"));
  EXPECT_NE(r.err.find("marchstudio-oiio.so"), std::string::npos);
}

TEST(StartUp, TheOsmesaBackendOpensLibOSMesa) {
  TempDir dir;
  const RunResult r = run_logged({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "32x18",
                                  "--backend", "osmesa", "-o", (dir / "o.png").string()},
                                 dir);
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(loaded(r, "libOSMesa.so.8"));
}

TEST(StartUp, AMissingImageModuleIsOneLineAndNoFile) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "32x18",
                                       "-o", (dir / "seed.tif").string()},
                                      dir.path(), "MARCH_IMAGE_MODULE=/nonexistent/marchstudio-oiio.so; export MARCH_IMAGE_MODULE; ");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.err.find("marchstudio: /nonexistent/marchstudio-oiio.so: cannot load the image I/O module"), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace ms::test
