// mesh/mesh.h's write_level_set(): a sphere's narrow band (distances
// computed here, analytically) written through marchstudio-vdb.so, then
// read back by OpenVDB's own Python binding (Debian's python3-openvdb,
// module pyopenvdb): one grid, its name, class and voxel size, negative
// inside, positive outside, and an active voxel's value as written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>

#include "core/error.h"
#include "files.h"
#include "mesh/mesh.h"

namespace ms {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

bool have_pyopenvdb() { return std::system("/usr/bin/python3 -c 'import pyopenvdb' >/dev/null 2>&1") == 0; }

// Radius 1 about the world origin, 0.1 voxels, the grid's voxel (0, 0, 0)
// at (-1.5, -1.5, -1.5): the centre is voxel (15, 15, 15).
LevelSetBand sphere_band() {
  LevelSetBand b;
  b.name = "sphere";
  b.voxel = 0.1;
  b.origin = glm::dvec3(-1.5);
  b.band = 0.3f;
  for (int i = 0; i <= 30; ++i)
    for (int j = 0; j <= 30; ++j)
      for (int k = 0; k <= 30; ++k) {
        const glm::dvec3 p = b.origin + b.voxel * glm::dvec3(i, j, k);
        const float d = static_cast<float>(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) - 1.0);
        if (std::fabs(d) < b.band) {
          b.ijk.emplace_back(i, j, k);
          b.value.push_back(d);
        }
      }
  return b;
}

std::string run(const std::string& cmd) {
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
    ::pclose(p);
  }
  return out;
}

TEST(LevelSet, ASphereReadsBackWithPyopenvdb) {
  if (!have_pyopenvdb()) GTEST_SKIP() << "no pyopenvdb (Debian's python3-openvdb)";
  TempDir dir;
  const LevelSetBand band = sphere_band();
  ASSERT_GT(band.ijk.size(), 1000u);
  const std::uint64_t active = write_level_set(band, dir / "sphere.vdb");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sphere.vdb"});
  // One voxel of the band (from the middle of its list): an active value to compare.
  const glm::ivec3 a = band.ijk[band.ijk.size() / 2];
  std::ostringstream script;
  script << "import pyopenvdb as vdb\n"
         << "grids, meta = vdb.readAll('" << (dir / "sphere.vdb").string() << "')\n"
         << "g = grids[0]\nacc = g.getConstAccessor()\n"
         << "print(len(grids)); print(g.name); print(g.gridClass)\n"
         << "print('%.9g' % g.transform.voxelSize()[0])\n"
         << "print('%.9g' % g.transform.indexToWorld((0, 0, 0))[0])\n"
         << "print('%.9g' % acc.getValue((15, 15, 15))); print('%.9g' % acc.getValue((0, 0, 0)))\n"
         << "print('%.9g' % acc.getValue((" << a.x << ", " << a.y << ", " << a.z << ")))\n"
         << "print(acc.isValueOn((" << a.x << ", " << a.y << ", " << a.z << ")))\n"
         << "print(g.activeVoxelCount())\n";
  test::write_file(dir / "read.py", script.str());
  std::istringstream out(run("/usr/bin/python3 " + (dir / "read.py").string() + " 2>&1"));
  std::vector<std::string> lines;
  for (std::string l; std::getline(out, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 10u) << out.str();
  EXPECT_EQ(lines[0], "1");
  EXPECT_EQ(lines[1], "sphere");
  EXPECT_EQ(lines[2], "level set");
  EXPECT_DOUBLE_EQ(std::stod(lines[3]), 0.1);
  EXPECT_DOUBLE_EQ(std::stod(lines[4]), -1.5);
  EXPECT_LT(std::stof(lines[5]), 0.0f) << "the centre is inside";
  EXPECT_GT(std::stof(lines[6]), 0.0f) << "a corner is outside";
  EXPECT_EQ(std::stof(lines[7]), band.value[band.value.size() / 2]);
  EXPECT_EQ(lines[8], "True");
  EXPECT_EQ(std::stoul(lines[9]), band.ijk.size());
  EXPECT_EQ(active, band.ijk.size());
}

// The exporter lists a voxel that two bricks share twice: the count
// returned is what the file holds, each voxel once.
TEST(LevelSet, TheCountReturnedIsTheFilesActiveVoxels) {
  if (!have_pyopenvdb()) GTEST_SKIP() << "no pyopenvdb (Debian's python3-openvdb)";
  TempDir dir;
  LevelSetBand band = sphere_band();
  const std::size_t unique = band.ijk.size();
  for (std::size_t i = 0; i < unique; i += 2) {
    band.ijk.push_back(band.ijk[i]);
    band.value.push_back(band.value[i]);
  }
  const std::uint64_t active = write_level_set(band, dir / "twice.vdb");
  const std::string out = run("/usr/bin/python3 -c \"import pyopenvdb as vdb; print(vdb.read('" +
                              (dir / "twice.vdb").string() + "', 'sphere').activeVoxelCount())\" 2>&1");
  EXPECT_EQ(active, unique);
  EXPECT_EQ(std::to_string(active) + "\n", out);
}

Exit code_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  return Exit::ok;
}

TEST(LevelSet, BadBandsAreBadInput) {
  TempDir dir;
  LevelSetBand b = sphere_band();
  b.voxel = 0.0;
  EXPECT_EQ(code_of([&] { write_level_set(b, dir / "s.vdb"); }), Exit::bad_input);
  b = sphere_band();
  b.value.pop_back();
  EXPECT_EQ(code_of([&] { write_level_set(b, dir / "s.vdb"); }), Exit::bad_input);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(LevelSet, AFullDeviceIsASystemError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  TempDir dir;
  fs::create_symlink("/dev/full", dir / "s.vdb");
  EXPECT_EQ(code_of([&] { write_level_set(sphere_band(), dir / "s.vdb"); }), Exit::system);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.vdb"});
}

// In a child process of its own (the module is looked up once per
// process): one Exit::system error naming the module, and no file.
[[noreturn]] void write_without_the_module() {
  int code = 0;
  {
    TempDir dir;
    ::setenv("MARCH_VDB_MODULE", "/nonexistent/marchstudio-vdb.so", 1);
    try {
      write_level_set(sphere_band(), dir / "s.vdb");
    } catch (const Error& e) {
      std::fprintf(stderr, "%s\n", format_error(e.info()).c_str());
      code = static_cast<int>(e.code());
    }
    if (!dir.entries().empty()) code = 99;
  }
  std::_Exit(code);
}

TEST(LevelSetDeathTest, AMissingModuleIsOneSystemErrorNamingIt) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(write_without_the_module(), ::testing::ExitedWithCode(3),
              "/nonexistent/marchstudio-vdb.so: cannot load the OpenVDB module");
}

}  // namespace
}  // namespace ms
