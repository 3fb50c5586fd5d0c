// `marchstudio mesh` writes normals from the scene's own field (the GPU's
// gradient, on llvmpipe): the seed's sphere in OBJ (`vn`, `f v//vn`) and
// PLY (nx ny nz) is smooth, one unit normal per vertex along the radius;
// a box with a bore keeps its creases: vertices there carry one normal
// per side, each its side's. The readers are tests/support/mesh_read.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "mesh_read.h"
#include "run.h"

namespace ms::test {
namespace {

ReadMesh export_as(const std::string& scene, const TempDir& dir, const std::string& name) {
  const RunResult r = run_marchstudio({"mesh", scene, "-o", (dir / name).string(), "--resolution", "32"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  ReadMesh m = name.size() > 4 && name.substr(name.size() - 4) == ".obj" ? read_obj(dir / name) : read_ply(dir / name);
  EXPECT_TRUE(m.ok) << name;
  EXPECT_FALSE(m.indices.empty()) << name;
  EXPECT_EQ(m.normal_index.size(), m.indices.size()) << name << ": no normals";
  return m;
}

TEST(MeshExportNormals, TheSeedSphereIsSmoothAndRadial) {
  TempDir dir;
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  for (const char* name : {"s.obj", "s.ply"}) {
    const ReadMesh m = export_as(seed, dir, name);
    if (m.normal_index.size() != m.indices.size()) continue;
    double worst = 0.0;
    for (std::size_t c = 0; c < m.indices.size(); ++c) {
      const glm::vec3 n = m.normals[m.normal_index[c]];
      ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << name;
      worst = std::max(worst, degrees(n, m.positions[m.indices[c]] - glm::vec3(0, 1, 0)));
    }
    EXPECT_LT(worst, 1.0) << name;
    EXPECT_EQ(m.normals.size(), m.positions.size()) << name << ": a smooth surface split";
  }
}

TEST(MeshExportNormals, ABoredBoxKeepsItsCreases) {
  TempDir dir;
  write_file(dir / "cut.glsl",
             "vec2 map(vec3 p) {\n"
             "  float box = sdBox(p - vec3(0.011, 0.0, 0.007), vec3(0.6, 0.3, 0.4));\n"
             "  float hole = length(p.xz - vec2(0.15, 0.05)) - 0.2137;\n"
             "  return vec2(max(box, -hole), MAT_PART);\n}\n");
  write_file(dir / "cut.toml", "[scene]\nname = \"cut\"\nmap = \"cut.glsl\"\n\n[bounds]\nmin = [-0.65, -0.35, -0.45]\n"
                               "max = [0.65, 0.35, 0.45]\n\n[[materials]]\nname = \"part\"\n");
  for (const char* name : {"c.obj", "c.ply"}) {
    const ReadMesh m = export_as((dir / "cut.toml").string(), dir, name);
    if (m.normal_index.size() != m.indices.size()) continue;
    // A corner on a box face has that face's normal, exactly as the GPU's
    // gradient gives it: one of the six axes.
    std::size_t on_faces = 0, split = 0;
    for (std::size_t c = 0; c < m.indices.size(); ++c) {
      const glm::vec3 n = m.normals[m.normal_index[c]];
      ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << name;
      on_faces += std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}) > 0.9999f;
    }
    // A vertex with several normals is on a crease: they are its sides',
    // far apart, and each corner there has its own triangle's side, within
    // the smoothing angle (a normal shared across the crease would be 45
    // degrees from both).
    const auto at = normals_at(m);
    for (const auto& [p, normals] : at) {
      if (normals.size() < 2) continue;
      ++split;
      double widest = 0.0;
      for (const auto& a : normals)
        for (const auto& b : normals)
          widest = std::max(widest, degrees({std::get<0>(a), std::get<1>(a), std::get<2>(a)},
                                            {std::get<0>(b), std::get<1>(b), std::get<2>(b)}));
      EXPECT_GT(widest, 45.0) << name;
    }
    for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
      const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                      c = m.positions[m.indices[3 * t + 2]];
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = m.positions[m.indices[3 * t + k]];
        if (at.at({p.x, p.y, p.z}).size() < 2) continue;
        EXPECT_LT(degrees(m.normals[m.normal_index[3 * t + k]], glm::cross(b - a, c - a)), 30.0) << name;
      }
    }
    EXPECT_GT(on_faces, m.indices.size() / 2) << name;
    // The box's edges and the bore's rims, at a voxel of 1.3 / 32.
    EXPECT_GT(split, 200u) << name;
  }
}

}  // namespace
}  // namespace ms::test
