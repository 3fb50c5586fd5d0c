// The field sampled only where the surface may be: bricks of 8^3 cells
// found hierarchically, a cube skipped (with all it holds) when its centre
// is farther from the surface than the field's Lipschitz bound lets any
// point inside be. Cost grows with the surface's area, not the volume.
//
//   MeshGrid grid = mesh_grid(lo, hi, 256, 0.0);    // 256 cells on the longest side
//   SparseField f = sample_sparse(source, grid, {lipschitz, band});
//   f.value({i, j, k});                             // a sampled voxel's value
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/field_source.h"

namespace ms {

constexpr int kBrick = 4;  // cells along a brick's side

struct MeshGrid {
  glm::dvec3 origin{0.0};  // world position of voxel (0, 0, 0)
  double voxel = 1.0;      // world units per cell
  glm::ivec3 cells{0};     // a multiple of kBrick on each axis
};

// A grid over [lo, hi] with `resolution` cells along its longest side (or
// cells of `voxel` world units when > 0), padded by two cells each side so
// that the clipped field is positive on its border.
MeshGrid mesh_grid(const glm::dvec3& lo, const glm::dvec3& hi, int resolution, double voxel);

struct SparseOptions {
  float lipschitz = 1.0f;  // |f(p) - f(q)| <= lipschitz |p - q|
  float band = 0.0f;       // keep every voxel within this many voxels of the surface too
  MeshProgress progress;   // may be empty
};

struct SparseField {
  MeshGrid grid;
  std::unordered_map<std::uint64_t, std::uint32_t> index;  // brick key -> brick slot
  // The same as a dense array over the grid's bricks (-1: skipped), when
  // it fits in kDenseBricks entries: the meshing passes look up bricks
  // millions of times, and an array is many times quicker than a hash.
  std::vector<std::int32_t> dense;
  std::vector<glm::ivec3> bricks;                          // slot -> brick coordinate
  std::vector<float> values;                               // slot * (kBrick+1)^3 + corner
  std::uint64_t cube_tests = 0;                            // coarse cubes evaluated

  static std::uint64_t key(const glm::ivec3& brick);
  // The slot of the brick holding cell `c`, or -1 when it was skipped.
  int slot_of_cell(const glm::ivec3& c) const;
  // Voxel `v` read from brick `slot` (v inside its closed range).
  float at(int slot, const glm::ivec3& v) const;
};

constexpr std::size_t kDenseBricks = std::size_t{1} << 26;

SparseField sample_sparse(FieldSource& source, const MeshGrid& grid, const SparseOptions& opts);

}  // namespace ms
