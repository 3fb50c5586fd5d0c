// Manifold dual contouring on analytic fields evaluated on the CPU (the GPU
// path is tests/cli/test_mesh.cpp): the mesh is closed, manifold, outward,
// free of self-intersections; its vertices lie on the surface; a box's
// corners land on the true corners; skipped bricks never hold surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "mesh/cell_table.h"
#include "mesh/dual_contour.h"
#include "mesh/mesh_check.h"
#include "mesh/sparse_field.h"
#include "mesh/untangle.h"
#include "analytic_field.h"

namespace ms {
namespace {

using test::Analytic;
using test::Field;

float box(const glm::vec3& p, const glm::vec3& c, const glm::vec3& b) {
  const glm::vec3 q = glm::abs(p - c) - b;
  return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

struct Result {
  DualContour dc;
  MeshCheck check;
  MeshAccuracy acc;
  MeshGrid grid;
  std::size_t evals = 0;
};

Result mesh_of(const Field& f, glm::dvec3 lo, glm::dvec3 hi, int res) {
  Result r;
  r.grid = mesh_grid(lo, hi, res, 0.0);
  Analytic src(f, r.grid);
  const SparseField sf = sample_sparse(src, r.grid, {});
  r.dc = dual_contour(src, sf);
  untangle(r.dc, r.grid);
  r.check = check_mesh(r.dc.mesh, r.grid.voxel);
  r.acc = measure_accuracy(src, r.dc, r.grid.voxel);
  r.evals = src.evals;
  return r;
}

TEST(MeshCells, FacesAgreeAndEveryCrossingHasAPatch) {
  for (int m = 1; m < 255; ++m) {
    const CellPatches& p = cell_patches(m);
    EXPECT_GE(p.count, 1) << m;
    EXPECT_LE(p.count, 4) << m;
    for (int e = 0; e < 12; ++e) {
      glm::ivec3 a = edge_start(e), b = a;
      b[edge_axis(e)] = 1;
      const bool ia = (m >> (a.x | a.y << 1 | a.z << 2)) & 1, ib = (m >> (b.x | b.y << 1 | b.z << 2)) & 1;
      EXPECT_EQ(p.patch[e] >= 0, ia != ib) << m << " edge " << e;
    }
  }
  EXPECT_EQ(cell_patches(0b10000001).count, 2);  // two opposite corners: two patches
}

TEST(MeshDualContour, ASphereIsClosedManifoldAndOnTheSurface) {
  const Result r = mesh_of([](const glm::vec3& p) { return glm::length(p) - 1.0f; }, {-1.02, -1.02, -1.02},
                           {1.02, 1.02, 1.02}, 64);
  EXPECT_TRUE(r.check.ok()) << r.check.summary();
  EXPECT_EQ(r.check.euler, 2);
  EXPECT_LT(r.acc.max_vertex, 0.05);
  EXPECT_LT(r.acc.hausdorff, 0.1);
  EXPECT_EQ(r.dc.missing, 0u);
}

// Hostile: clusters of spheres a voxel or two across, touching and
// nearly touching, min-combined and smooth-combined, at coarse grids where
// cells hold several patches and faces are ambiguous. Every mesh must pass
// the check (closed, manifold, oriented, no self-intersections).
TEST(MeshDualContour, RandomSphereClustersAreAlwaysManifold) {
  std::uint32_t seed = 12345;
  auto rnd = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<float>(seed >> 8) / 16777216.0f;
  };
  for (int trial = 0; trial < 24; ++trial) {
    std::vector<glm::vec4> balls;
    for (int i = 0; i < 12; ++i)
      balls.emplace_back(rnd() - 0.5f, rnd() - 0.5f, rnd() - 0.5f, 0.03f + 0.12f * rnd());
    const bool smooth = trial % 2 == 1;
    const Field f = [&balls, smooth](const glm::vec3& p) {
      float d = 1e9f;
      for (const glm::vec4& b : balls) {
        const float s = glm::length(p - glm::vec3(b)) - b.w;
        if (!smooth) {
          d = std::min(d, s);
        } else {
          const float k = 0.05f, h = std::max(k - std::abs(d - s), 0.0f) / k;
          d = std::min(d, s) - h * h * k * 0.25f;
        }
      }
      return d;
    };
    const Result r = mesh_of(f, {-0.75, -0.75, -0.75}, {0.75, 0.75, 0.75}, 24 + trial);
    EXPECT_TRUE(r.check.ok()) << "trial " << trial << ": " << r.check.summary();
  }
}

TEST(MeshSparseField, CostGrowsWithAreaNotVolume) {
  const Field sphere = [](const glm::vec3& p) { return glm::length(p) - 1.0f; };
  const Result a = mesh_of(sphere, {-1.02, -1.02, -1.02}, {1.02, 1.02, 1.02}, 64);
  const Result b = mesh_of(sphere, {-1.02, -1.02, -1.02}, {1.02, 1.02, 1.02}, 128);
  // Twice the resolution: four times the area, eight times the volume.
  EXPECT_LT(static_cast<double>(b.evals) / a.evals, 5.0) << a.evals << " -> " << b.evals;
  const double dense = std::pow(b.grid.cells.x + 1.0, 3.0);
  EXPECT_LT(static_cast<double>(b.evals), dense);
}

// The memory budget's hook: told the bricks ahead before they are
// sampled, from the first level on, and a throw there stops the sampling.
TEST(MeshSparseField, TheBricksAheadAreToldBeforeTheyAreSampled) {
  const Field sphere = [](const glm::vec3& p) { return glm::length(p) - 1.0f; };
  const MeshGrid grid = mesh_grid({-1.02, -1.02, -1.02}, {1.02, 1.02, 1.02}, 128, 0.0);
  Analytic src(sphere, grid);
  SparseOptions opts;
  std::vector<double> told;
  opts.bricks_ahead = [&](double bricks) { told.push_back(bricks); };
  const SparseField f = sample_sparse(src, grid, opts);
  ASSERT_GE(told.size(), 3u);
  EXPECT_EQ(told.back(), static_cast<double>(f.bricks.size())) << "the last count is exact";
  // Each level's estimate is of the surface's size, not the volume's.
  const double bricks = static_cast<double>(f.bricks.size());
  for (double t : told) {
    EXPECT_GT(t, 0.5 * bricks) << t;
    EXPECT_LT(t, 2.0 * bricks) << t;
  }
  // Over budget at the first level: stopped after its cells, no brick sampled.
  Analytic stopped(sphere, grid);
  opts.bricks_ahead = [](double) { throw std::runtime_error("over budget"); };
  EXPECT_THROW(sample_sparse(stopped, grid, opts), std::runtime_error);
  EXPECT_LE(stopped.evals, 512u);
}

TEST(MeshDualContour, ABoxKeepsItsCornersAndEdges) {
  // Off the grid on purpose: no face on a grid plane.
  const glm::vec3 c(0.013f, -0.021f, 0.007f), b(0.61f, 0.43f, 0.37f);
  const Result r = mesh_of([&](const glm::vec3& p) { return box(p, c, b); }, {-0.7, -0.5, -0.45}, {0.7, 0.5, 0.45}, 64);
  EXPECT_TRUE(r.check.ok()) << r.check.summary();
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner = c + b * glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    float best = 1e9f;
    for (const glm::vec3& v : r.dc.mesh.positions) best = std::min(best, glm::length(v - corner));
    EXPECT_LT(best / r.grid.voxel, 0.1) << "corner " << k;
  }
  EXPECT_LT(r.acc.max_vertex, 0.05);
}

TEST(MeshDualContour, TwoTouchingSpheresStayManifold) {
  // A neck thinner than a voxel: cells with two patches.
  const Result r = mesh_of(
      [](const glm::vec3& p) {
        return std::min(glm::length(p - glm::vec3(-0.5f, 0, 0)) - 0.5f, glm::length(p - glm::vec3(0.503f, 0, 0)) - 0.5f);
      },
      {-1.02, -0.52, -0.52}, {1.02, 0.52, 0.52}, 48);
  EXPECT_TRUE(r.check.ok()) << r.check.summary();
}

}  // namespace
}  // namespace ms

namespace ms {
namespace {

// A closed cube of 12 triangles, counter-clockwise from outside, at `o`.
void add_cube(TriMesh& m, const glm::vec3& o, float s = 1.0f) {
  const std::uint32_t base = static_cast<std::uint32_t>(m.positions.size());
  for (int i = 0; i < 8; ++i) m.positions.push_back(o + s * glm::vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q)
    for (std::uint32_t k : {f[0], f[1], f[2], f[0], f[2], f[3]}) m.indices.push_back(base + k);
  m.material.resize(m.positions.size(), 0);
}

TEST(MeshCheck, ACubeIsClosedAndEveryFaultIsFound) {
  TriMesh cube;
  add_cube(cube, glm::vec3(0.0f));
  MeshCheck c = check_mesh(cube, 0.1);
  EXPECT_TRUE(c.ok()) << c.summary();
  EXPECT_EQ(c.euler, 2);
  EXPECT_NEAR(c.volume, 1.0, 1e-6);

  TriMesh hole = cube;
  hole.indices.resize(hole.indices.size() - 3);
  EXPECT_EQ(check_mesh(hole, 0.1).boundary_edges, 3u);

  TriMesh flipped = cube;
  std::swap(flipped.indices[1], flipped.indices[2]);
  EXPECT_GT(check_mesh(flipped, 0.1).flipped_edges, 0u);

  TriMesh inside_out = cube;
  for (std::size_t t = 0; t < inside_out.triangles(); ++t) std::swap(inside_out.indices[t * 3 + 1], inside_out.indices[t * 3 + 2]);
  c = check_mesh(inside_out, 0.1);
  EXPECT_FALSE(c.ok());
  EXPECT_LT(c.volume, 0.0);

  TriMesh overlapping = cube;
  add_cube(overlapping, glm::vec3(0.5f, 0.3f, 0.2f));
  EXPECT_GT(check_mesh(overlapping, 0.5).self_intersections, 0u);

  // Two cubes sharing one corner vertex: closed, but that vertex has two fans.
  TriMesh bowtie = cube;
  add_cube(bowtie, glm::vec3(1.0f));
  for (std::uint32_t& i : bowtie.indices)
    if (i == 8) i = 7;
  c = check_mesh(bowtie, 0.5);
  EXPECT_EQ(c.nonmanifold_vertices, 1u);
  EXPECT_EQ(c.boundary_edges, 0u);
}

}  // namespace
}  // namespace ms
