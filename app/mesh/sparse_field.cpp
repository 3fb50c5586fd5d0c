#include "mesh/sparse_field.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace ms {

namespace {

// The bricks kept around a surface are a shell about this many bricks
// thick: those within a brick's half-diagonal of it, and their neighbours.
constexpr double kShell = 2.5;

glm::ivec3 brick_of(const glm::ivec3& c) {
  return {c.x >= 0 ? c.x / kBrick : -1, c.y >= 0 ? c.y / kBrick : -1, c.z >= 0 ? c.z / kBrick : -1};
}

// Whether a cube of `side` voxels whose centre reads `d` may hold a point
// within `band` voxels of the surface. The 1e-3 voxel slack covers the
// float rounding of the two positions the test compares.
bool may_hold(float d, int side, const SparseOptions& o, double voxel) {
  const double r = 0.5 * std::sqrt(3.0) * side;
  return std::abs(d) <= (o.lipschitz * (r + 1e-3) + o.band) * voxel;
}

// Whether a sign change inside brick values `v` reaches the part of its
// border it shares with the neighbour at offset `side` (each axis -1, 0
// or 1): a corner there whose neighbour along an axis, in the brick,
// has the other sign.
bool reaches(const float* v, const glm::ivec3& side) {
  for (int i = 0; i < kBrickCorners; ++i) {
    const glm::ivec3 l = SparseField::corner_at(i);
    bool on = true;
    for (int a = 0; a < 3; ++a) on = on && (side[a] == 0 || l[a] == (side[a] < 0 ? 0 : kBrick));
    if (!on) continue;
    for (int a = 0; a < 3; ++a)
      for (int o = -1; o <= 1; o += 2) {
        glm::ivec3 m = l;
        m[a] += o;
        if (m[a] >= 0 && m[a] <= kBrick && (v[SparseField::corner_index(m)] < 0.0f) != (v[i] < 0.0f)) return true;
      }
  }
  return false;
}

// The skipped bricks a sign change of the bricks from `from` on reaches
// (a field that breaks its Lipschitz bound, or rounding): their coordinates.
std::vector<glm::ivec3> missing_neighbours(const SparseField& f, std::size_t from) {
  std::vector<glm::ivec3> out;
  std::unordered_set<std::uint64_t> seen;
  const glm::ivec3 nb = f.grid.cells / kBrick;
  for (std::size_t s = from; s < f.bricks.size(); ++s) {
    if (!f.changes_sign(s)) continue;
    for (int d = 0; d < 27; ++d) {
      const glm::ivec3 side(d % 3 - 1, (d / 3) % 3 - 1, d / 9 - 1), b = f.bricks[s] + side;
      if (b.x < 0 || b.y < 0 || b.z < 0 || b.x >= nb.x || b.y >= nb.y || b.z >= nb.z) continue;
      const std::uint64_t k = SparseField::key(b);
      if (f.index.count(k) || seen.count(k) || !reaches(f.brick_values(s), side)) continue;
      seen.insert(k);
      out.push_back(b);
    }
  }
  return out;
}

void add_bricks(FieldSource& source, SparseField& f, const std::vector<glm::ivec3>& bricks) {
  std::vector<glm::ivec3> first(bricks.size());
  for (std::size_t i = 0; i < bricks.size(); ++i) first[i] = bricks[i] * kBrick;
  const std::vector<float> v = source.bricks(first, kBrick);
  f.samples += v.size();
  for (const float x : v) f.nonfinite += !std::isfinite(x);
  for (const glm::ivec3& b : bricks) {
    f.index[SparseField::key(b)] = static_cast<std::uint32_t>(f.bricks.size());
    f.bricks.push_back(b);
  }
  f.values.insert(f.values.end(), v.begin(), v.end());
}

}  // namespace

std::uint64_t SparseField::key(const glm::ivec3& b) {
  return (static_cast<std::uint64_t>(b.x) << 42) | (static_cast<std::uint64_t>(b.y) << 21) |
         static_cast<std::uint64_t>(b.z);
}

int SparseField::slot_of_cell(const glm::ivec3& c) const {
  if (!dense.empty()) {
    const glm::ivec3 nb = grid.cells / kBrick, b = brick_of(c);
    if (b.x < 0 || b.y < 0 || b.z < 0 || b.x >= nb.x || b.y >= nb.y || b.z >= nb.z) return -1;
    return dense[(static_cast<std::size_t>(b.z) * nb.y + b.y) * nb.x + b.x];
  }
  const auto it = index.find(key(brick_of(c)));
  return it == index.end() ? -1 : static_cast<int>(it->second);
}

bool SparseField::changes_sign(std::size_t slot) const {
  const float* v = brick_values(slot);
  bool neg = false, pos = false;
  for (int i = 0; i < kBrickCorners && !(neg && pos); ++i) (v[i] < 0.0f ? neg : pos) = true;
  return neg && pos;
}

long SparseField::cell_index(const glm::ivec3& c) const {
  const int slot = slot_of_cell(c);
  if (slot < 0) return -1;
  const glm::ivec3 l = c - bricks[static_cast<std::size_t>(slot)] * kBrick;
  return static_cast<long>(slot) * kBrickCells + (l.z * kBrick + l.y) * kBrick + l.x;
}

glm::ivec3 SparseField::cell_at(std::size_t index) const {
  const int l = static_cast<int>(index % kBrickCells);
  return bricks[index / kBrickCells] * kBrick + glm::ivec3(l % kBrick, (l / kBrick) % kBrick, l / (kBrick * kBrick));
}

MeshGrid mesh_grid(const glm::dvec3& lo, const glm::dvec3& hi, int resolution, double voxel) {
  MeshGrid g;
  const glm::dvec3 size = hi - lo;
  g.voxel = voxel > 0.0 ? voxel : std::max({size.x, size.y, size.z}) / std::max(resolution, 1);
  for (int a = 0; a < 3; ++a) {
    const int n = static_cast<int>(std::ceil(size[a] / g.voxel - 1e-9)) + 4;
    g.cells[a] = (n + kBrick - 1) / kBrick * kBrick;
    // Centred: the padding splits evenly around the box.
    g.origin[a] = 0.5 * (lo[a] + hi[a]) - 0.5 * g.cells[a] * g.voxel;
  }
  return g;
}

SparseField sample_sparse(FieldSource& source, const MeshGrid& grid, const SparseOptions& opts) {
  SparseField f;
  f.grid = grid;
  int side = kBrick;
  while (side * 8 < std::max({grid.cells.x, grid.cells.y, grid.cells.z})) side *= 2;
  std::vector<glm::ivec4> cubes;
  for (int z = 0; z < grid.cells.z; z += side)
    for (int y = 0; y < grid.cells.y; y += side)
      for (int x = 0; x < grid.cells.x; x += side) cubes.emplace_back(x, y, z, side);
  // Coarse to fine: each kept cube's eight children, down to bricks.
  for (int level = 0;; ++level) {
    if (opts.progress) opts.progress("sampling", 0.05 * level / 8.0);
    const std::vector<float> d = source.cells(cubes);
    f.samples += d.size();
    double ahead = 0.0;
    for (std::size_t i = 0; i < cubes.size(); ++i) {
      f.nonfinite += !std::isfinite(d[i]);
      if (may_hold(d[i], cubes[i].w, opts, grid.voxel)) ahead += kShell * std::pow(cubes[i].w / kBrick, 2);
    }
    if (opts.bricks_ahead) opts.bricks_ahead(ahead);
    std::vector<glm::ivec4> next;
    for (std::size_t i = 0; i < cubes.size(); ++i) {
      const glm::ivec4 c = cubes[i];
      if (!may_hold(d[i], c.w, opts, grid.voxel)) continue;
      if (c.w == kBrick) {
        next.push_back(c);
        continue;
      }
      const int h = c.w / 2;
      for (int k = 0; k < 8; ++k) {
        const glm::ivec3 o(c.x + (k & 1) * h, c.y + ((k >> 1) & 1) * h, c.z + ((k >> 2) & 1) * h);
        if (o.x < grid.cells.x && o.y < grid.cells.y && o.z < grid.cells.z) next.emplace_back(o, h);
      }
    }
    cubes.swap(next);
    if (cubes.empty() || cubes.front().w == kBrick) break;
  }
  std::vector<glm::ivec3> bricks;
  for (const glm::ivec4& c : cubes) bricks.push_back(glm::ivec3(c) / kBrick);
  if (opts.progress) opts.progress("sampling", 0.1);
  if (opts.bricks_ahead) opts.bricks_ahead(static_cast<double>(bricks.size()));
  add_bricks(source, f, bricks);
  // A surface that leaves a brick into a skipped one: sample that too.
  for (std::size_t from = 0, round = 0; round < 4; ++round) {
    const std::vector<glm::ivec3> more = missing_neighbours(f, from);
    if (more.empty()) break;
    if (opts.bricks_ahead) opts.bricks_ahead(static_cast<double>(f.bricks.size() + more.size()));
    from = f.bricks.size();
    add_bricks(source, f, more);
  }
  const glm::ivec3 nb = grid.cells / kBrick;
  if (static_cast<std::size_t>(nb.x) * nb.y * nb.z <= kDenseBricks) {
    f.dense.assign(static_cast<std::size_t>(nb.x) * nb.y * nb.z, -1);
    for (std::size_t s = 0; s < f.bricks.size(); ++s) {
      const glm::ivec3 b = f.bricks[s];
      f.dense[(static_cast<std::size_t>(b.z) * nb.y + b.y) * nb.x + b.x] = static_cast<std::int32_t>(s);
    }
  }
  return f;
}

}  // namespace ms
