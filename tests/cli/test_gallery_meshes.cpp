// The gallery's scenes of modifiers and profiles (scenes/flange,
// profiles, lattice, assembly) mesh watertight at --resolution 256: the mesher's own
// check says so, and read back, every edge of the file is shared by
// exactly two triangles, each way round once. (The lattice takes about 30 s.)
#include <gtest/gtest.h>

#include <map>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "files.h"
#include "mesh_read.h"
#include "run.h"

namespace ms::test {
namespace {

class GalleryMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(GalleryMesh, IsWatertightAt256) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes" / (std::string(GetParam()) + ".toml")).string();
  const RunResult r = run_marchstudio({"mesh", scene, "-o", (dir / "m.ply").string(), "--resolution", "256", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["manifold"].get<bool>()) << j["check"]["summary"];
  const ReadMesh m = read_ply(dir / "m.ply");
  ASSERT_TRUE(m.ok);
  ASSERT_GT(m.indices.size(), 3000u);
  // A vertex is written once per normal where a crease splits it: welded
  // by position, every directed edge of a closed, consistently wound
  // surface appears once and its reverse once.
  std::map<std::tuple<float, float, float>, std::uint32_t> weld;
  std::vector<std::uint32_t> id;
  for (const glm::vec3& p : m.positions)
    id.push_back(weld.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<std::uint32_t>(weld.size())).first->second);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) ++edges[{id[m.indices[t + k]], id[m.indices[t + (k + 1) % 3]]}];
  int open = 0, doubled = 0;
  for (const auto& [e, n] : edges) {
    doubled += n != 1;
    open += edges.count({e.second, e.first}) == 0;
  }
  EXPECT_EQ(open, 0);
  EXPECT_EQ(doubled, 0);
}

INSTANTIATE_TEST_SUITE_P(, GalleryMesh, ::testing::Values("flange", "profiles", "lattice", "assembly"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return std::string(i.param); });

}  // namespace
}  // namespace ms::test
