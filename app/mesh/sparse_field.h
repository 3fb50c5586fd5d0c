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
#include <functional>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/field_source.h"

namespace ms {

constexpr int kBrick = 4;  // cells along a brick's side
constexpr int kBrickCells = kBrick * kBrick * kBrick;
constexpr int kBrickCorners = (kBrick + 1) * (kBrick + 1) * (kBrick + 1);

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
  // Told the bricks the export is about to hold, before they are sampled
  // (may be empty; may throw to stop): during the descent an estimate from
  // each level's kept cubes (a surface through a cube of side s crosses
  // about (s / kBrick)^2 of its bricks, in a shell of them 2.5 thick),
  // then each list's exact count.
  std::function<void(double bricks)> bricks_ahead;
};

struct SparseField {
  MeshGrid grid;
  std::unordered_map<std::uint64_t, std::uint32_t> index;  // brick key -> brick slot
  // The same as a dense array over the grid's bricks (-1: skipped), when
  // it fits in kDenseBricks entries: the meshing passes look up bricks
  // millions of times, and an array is many times quicker than a hash.
  std::vector<std::int32_t> dense;
  std::vector<glm::ivec3> bricks;                          // slot -> brick coordinate
  std::vector<float> values;                               // slot * kBrickCorners + corner_index()
  std::size_t samples = 0, nonfinite = 0;                  // values read, and those NaN or Inf

  static std::uint64_t key(const glm::ivec3& brick);
  // Corner l of a brick (0..kBrick on each axis): its offset in the
  // brick's values, x fastest; corner_at() is the inverse.
  static int corner_index(const glm::ivec3& l) { return (l.z * (kBrick + 1) + l.y) * (kBrick + 1) + l.x; }
  static glm::ivec3 corner_at(int i) {
    constexpr int n = kBrick + 1;
    return {i % n, (i / n) % n, i / (n * n)};
  }
  const float* brick_values(std::size_t slot) const { return &values[slot * kBrickCorners]; }
  // Whether the brick's corners differ in sign: only such a brick holds surface.
  bool changes_sign(std::size_t slot) const;
  // The slot of the brick holding cell `c`, or -1 when it was skipped.
  int slot_of_cell(const glm::ivec3& c) const;
  // Cell `c` among every sampled cell (slot * kBrickCells + its place in
  // the brick, x fastest), or -1 when its brick was skipped; cell_at() is
  // the inverse. The meshing passes keep their per-cell tables so.
  long cell_index(const glm::ivec3& c) const;
  glm::ivec3 cell_at(std::size_t index) const;
};

// What an export holds per brick sampled, at its peak (the values, the
// contouring's per-cell tables, a surface brick's vertices, triangles and
// their check): 3.9 KB on the seed at 512 cells, 5.1 KB on a gyroid of a
// period of 25 cells (a surface folded inside every brick holds more).
constexpr double kBytesPerBrick = 4096;

constexpr std::size_t kDenseBricks = std::size_t{1} << 26;

SparseField sample_sparse(FieldSource& source, const MeshGrid& grid, const SparseOptions& opts);

}  // namespace ms
