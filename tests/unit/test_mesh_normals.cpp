// The normals `marchstudio mesh` writes (mesh/vertex_normals.h and the
// writers), read back from each file (OBJ, PLY by hand, GLB with tinygltf):
// unit length; on a sphere each within half a degree of the radial
// direction and no vertex split; on a box minus a cylinder each corner's
// normal its own side's (the faces' on the box, the radial on the bore),
// so a crease's vertex carries one per side, and only creases are split.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "analytic_field.h"
#include "core/error.h"
#include "files.h"
#include "mesh/dual_contour.h"
#include "mesh/mesh_check.h"
#include "mesh/untangle.h"
#include "mesh/vertex_normals.h"
#include "mesh_read.h"

namespace ms {
namespace {
namespace fs = std::filesystem;
using test::degrees;
using test::normals_at;
using test::ReadMesh;
using test::TempDir;

// The field meshed as the exporter does, then written and read back in each format.
TriMesh contour(const test::Field& f, const glm::dvec3& lo, const glm::dvec3& hi, int res, double* voxel = nullptr) {
  const MeshGrid grid = mesh_grid(lo, hi, res, 0.0);
  test::Analytic src(f, grid);
  DualContour dc = dual_contour(src, sample_sparse(src, grid, {}));
  untangle(dc, grid);
  vertex_normals(src, dc);
  measure_accuracy(src, dc, grid.voxel);
  EXPECT_TRUE(check_mesh(dc.mesh, grid.voxel).ok());
  if (voxel) *voxel = grid.voxel;
  return std::move(dc.mesh);
}

template <class T>
T at(const std::vector<unsigned char>& b, std::size_t offset) {
  T v;
  std::memcpy(&v, b.data() + offset, sizeof v);
  return v;
}

// One accessor's VEC3 or index elements, through its buffer view.
std::vector<glm::vec3> vec3s(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(accessor)];
  const tinygltf::BufferView& v = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::size_t stride = v.byteStride ? v.byteStride : 12;
  std::vector<glm::vec3> out;
  for (std::size_t i = 0; i < a.count; ++i)
    out.push_back(at<glm::vec3>(m.buffers[0].data, v.byteOffset + a.byteOffset + stride * i));
  return out;
}

ReadMesh read_glb(const fs::path& file) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  ReadMesh r;
  r.ok = loader.LoadBinaryFromFile(&model, &err, &warn, file.string());
  EXPECT_TRUE(r.ok) << err;
  if (!r.ok) return r;
  for (const tinygltf::Primitive& p : model.meshes.at(0).primitives) {
    EXPECT_EQ(p.attributes.count("NORMAL"), 1u);
    if (r.positions.empty()) {
      r.positions = vec3s(model, p.attributes.at("POSITION"));
      r.normals = vec3s(model, p.attributes.at("NORMAL"));
    }
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(p.indices)];
    const tinygltf::BufferView& v = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    for (std::size_t i = 0; i < a.count; ++i)
      r.indices.push_back(at<std::uint32_t>(model.buffers[0].data, v.byteOffset + a.byteOffset + 4 * i));
  }
  r.normal_index = r.indices;
  return r;
}

ReadMesh written(const TriMesh& m, const TempDir& dir, const std::string& name) {
  const fs::path file = dir / name;
  write_mesh(m, {}, file);
  const std::string ext = file.extension().string();
  ReadMesh r = ext == ".obj" ? test::read_obj(file) : ext == ".ply" ? test::read_ply(file) : read_glb(file);
  EXPECT_TRUE(r.ok) << name;
  EXPECT_EQ(r.normal_index.size(), r.indices.size()) << name;
  return r;
}

const char* const kFormats[] = {"m.obj", "m.ply", "m.glb"};

TEST(MeshNormals, ASphereIsSmoothAndRadial) {
  const glm::vec3 c(0.031f, -0.017f, 0.009f);
  const TriMesh m = contour([&](const glm::vec3& p) { return glm::length(p - c) - 0.8f; }, glm::dvec3(-1), glm::dvec3(1),
                            32);
  TempDir dir;
  for (const char* name : kFormats) {
    const ReadMesh r = written(m, dir, name);
    ASSERT_FALSE(r.indices.empty()) << name;
    double worst = 0.0;
    for (std::size_t k = 0; k < r.indices.size(); ++k) {
      const glm::vec3 n = r.normals[r.normal_index[k]];
      ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << name;
      worst = std::max(worst, degrees(n, r.positions[r.indices[k]] - c));
    }
    // The field's gradient at each vertex: the faces' mean would be 2 degrees off.
    EXPECT_LT(worst, 0.5) << name;
    // Nothing split: one normal per position, as many vertices as the mesh.
    for (const auto& [p, normals] : normals_at(r)) EXPECT_EQ(normals.size(), 1u) << name;
    EXPECT_EQ(r.positions.size(), m.positions.size()) << name;
  }
}

// A box with a bore along y through it: creases along the box's twelve
// edges and the bore's two rims, all at right angles.
const glm::vec3 kBoxCentre(0.011f, 0.0f, 0.007f), kBoxHalf(0.6f, 0.3f, 0.4f), kBoreAxis(0.15f, 0.0f, 0.05f);
constexpr float kBoreRadius = 0.2137f;

float sd_box(const glm::vec3& p) {
  const glm::vec3 q = glm::abs(p - kBoxCentre) - kBoxHalf;
  return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}
float sd_bore(const glm::vec3& p) { return glm::length(glm::vec2(p.x - kBoreAxis.x, p.z - kBoreAxis.z)) - kBoreRadius; }
float bored_box(const glm::vec3& p) { return std::max(sd_box(p), -sd_bore(p)); }

// Within `d` of a crease: two of the box's faces, or the box's top or
// bottom and the bore.
bool near_crease(const glm::vec3& p, float d) {
  const glm::vec3 q = glm::abs(glm::abs(p - kBoxCentre) - kBoxHalf);
  const int faces = (q.x < d) + (q.y < d) + (q.z < d);
  return faces >= 2 || (q.y < d && std::abs(sd_bore(p)) < d);
}

TEST(MeshNormals, ABoredBoxKeepsItsCreasesSharpAndNothingElseSplit) {
  double voxel = 0.0;
  const TriMesh m = contour(bored_box, glm::dvec3(-0.65, -0.35, -0.45), glm::dvec3(0.65, 0.35, 0.45), 48, &voxel);
  const test::Analytic field(bored_box, mesh_grid(glm::dvec3(-0.65, -0.35, -0.45), glm::dvec3(0.65, 0.35, 0.45), 48, 0.0));
  TempDir dir;
  for (const char* name : kFormats) {
    const ReadMesh r = written(m, dir, name);
    ASSERT_FALSE(r.indices.empty()) << name;
    // Each corner's normal is its own side's: the surface's a quarter of
    // the way from the corner into its triangle. Flat faces exactly, the bore
    // within a few degrees (its faces' mean at a rim).
    double flat = 0.0, bore = 0.0;
    for (std::size_t t = 0; t < r.indices.size() / 3; ++t) {
      const glm::vec3 centroid =
          (r.positions[r.indices[3 * t]] + r.positions[r.indices[3 * t + 1]] + r.positions[r.indices[3 * t + 2]]) / 3.0f;
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = r.positions[r.indices[3 * t + k]], n = r.normals[r.normal_index[3 * t + k]];
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << name;
        const glm::vec3 inside = p + 0.25f * (centroid - p);
        double& worst = -sd_bore(inside) > sd_box(inside) ? bore : flat;
        worst = std::max(worst, degrees(n, field.gradient(inside)));
      }
    }
    EXPECT_LT(flat, 0.5) << name;
    EXPECT_LT(bore, 5.0) << name;
    // Split only on the creases, and all along them.
    std::size_t split = 0;
    for (const auto& [p, normals] : normals_at(r)) {
      if (normals.size() < 2) continue;
      ++split;
      const glm::vec3 v(std::get<0>(p), std::get<1>(p), std::get<2>(p));
      EXPECT_TRUE(near_crease(v, static_cast<float>(voxel))) << name << ": split at " << v.x << ", " << v.y << ", " << v.z;
    }
    // The box's edges are 4 * (1.2 + 0.6 + 0.8) long, the rims 2 * 2 pi r.
    EXPECT_GT(static_cast<double>(split), 0.9 * (4 * 2.6 + 4 * M_PI * kBoreRadius) / voxel) << name;
  }
}

// The writers on a mesh that is all creases: a tetrahedron, each corner
// its face's normal. OBJ keeps 4 positions and 4 normals; PLY and GLB
// write each position once per normal, 12 vertices.
TEST(MeshNormals, EachFormatWritesACornersOwnNormal) {
  TriMesh m;
  m.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
  m.indices = {1, 2, 3, 0, 2, 1, 0, 1, 3, 0, 3, 2};
  for (std::size_t t = 0; t < 4; ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]];
    m.normals.push_back(glm::normalize(
        glm::cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a)));
    m.normal_index.insert(m.normal_index.end(), 3, static_cast<std::uint32_t>(t));
  }
  TempDir dir;
  for (const char* name : kFormats) {
    const ReadMesh r = written(m, dir, name);
    ASSERT_EQ(r.indices.size(), 12u) << name;
    EXPECT_EQ(r.positions.size(), std::string(name) == "m.obj" ? 4u : 12u) << name;
    EXPECT_EQ(r.normals.size(), std::string(name) == "m.obj" ? 4u : 12u) << name;
    std::multiset<std::tuple<float, float, float, int>> got, want;
    for (std::size_t c = 0; c < 12; ++c) {
      const glm::vec3 p = r.positions[r.indices[c]], n = r.normals[r.normal_index[c]];
      EXPECT_EQ(n, m.normals[c / 3]) << name << " corner " << c;
      got.emplace(p.x, p.y, p.z, 0);
      want.emplace(m.positions[m.indices[c]].x, m.positions[m.indices[c]].y, m.positions[m.indices[c]].z, 0);
    }
    EXPECT_EQ(got, want) << name;
  }
}

TEST(MeshNormals, ANormalIndexOutOfRangeIsBadInput) {
  TriMesh m;
  m.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  m.indices = {0, 1, 2};
  m.normals = {glm::vec3(0, 0, 1)};
  m.normal_index = {0, 0, 1};
  TempDir dir;
  for (const char* name : kFormats) {
    try {
      write_mesh(m, {}, dir / name);
      ADD_FAILURE() << name << " was written";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Exit::bad_input) << name;
    }
  }
  m.normal_index = {0, 0};
  EXPECT_THROW(write_mesh(m, {}, dir / "m.ply"), Error);
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace ms
