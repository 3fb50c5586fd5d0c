// A .vdb export's report counts what the file holds: `--json`'s
// band_voxels and the -v summary line equal the active voxels OpenVDB's
// own Python binding reads back (pyopenvdb; skipped without it).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "run.h"

namespace ms::test {
namespace {

bool have_pyopenvdb() { return std::system("/usr/bin/python3 -c 'import pyopenvdb' >/dev/null 2>&1") == 0; }

std::string active_voxels(const std::filesystem::path& file) {
  const std::string cmd = "/usr/bin/python3 -c \"import pyopenvdb as vdb; print(vdb.readAll('" + file.string() +
                          "')[0][0].activeVoxelCount())\" 2>&1";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
    ::pclose(p);
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

TEST(MeshVdbReport, TheCountIsTheWrittenGridsActiveVoxels) {
  if (!have_pyopenvdb()) GTEST_SKIP() << "no pyopenvdb (Debian's python3-openvdb)";
  TempDir dir;
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  const RunResult j = run_marchstudio({"mesh", seed, "-o", (dir / "a.vdb").string(), "--resolution", "32", "--json"},
                                      dir.path());
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const std::string read = active_voxels(dir / "a.vdb");
  ASSERT_GT(std::atol(read.c_str()), 0) << read;
  EXPECT_EQ(std::to_string(nlohmann::json::parse(j.out)["band_voxels"].get<std::uint64_t>()), read);

  const RunResult v = run_marchstudio({"mesh", seed, "-o", (dir / "b.vdb").string(), "--resolution", "32", "-v"},
                                      dir.path());
  ASSERT_EQ(v.exit_code, 0) << v.err;
  EXPECT_NE(v.err.find("level set, " + active_voxels(dir / "b.vdb") + " active voxels"), std::string::npos) << v.err;
}

}  // namespace
}  // namespace ms::test
