#include "mesh/untangle.h"

#include <vector>

#include <glm/geometric.hpp>

#include "mesh/cell_table.h"
#include "mesh/mesh_check.h"

namespace ms {

std::size_t untangle(DualContour& dc, const MeshGrid& grid) {
  TriMesh& m = dc.mesh;
  // How many vertices share each cell: a cell of one patch goes to its centre.
  std::vector<std::uint8_t> split(m.positions.size(), 0);
  for (std::size_t i = 1; i < m.positions.size(); ++i)
    if (dc.cell[i] == dc.cell[i - 1]) split[i] = split[i - 1] = 1;
  std::vector<std::uint8_t> moved(m.positions.size(), 0);
  // Each round moves the vertices of the triangles that still cross half
  // way to their safe place, the last all the way.
  constexpr int kRounds = 5;
  for (int round = 0; round < kRounds; ++round) {
    const auto pairs = crossing_pairs(m, grid.voxel);
    if (pairs.empty()) return 0;
    std::vector<std::uint8_t> pick(m.positions.size(), 0);
    for (const auto& [s, t] : pairs)
      for (std::uint32_t tri : {s, t})
        for (int k = 0; k < 3; ++k) pick[m.indices[std::size_t{tri} * 3 + k]] = 1;
    const float w = round + 1 == kRounds ? 1.0f : 0.5f;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      if (!pick[i]) continue;
      const glm::vec3 safe = split[i] ? dc.mass[i]
                                      : glm::vec3(grid.origin + (glm::dvec3(dc.cell[i]) + 0.5) * grid.voxel);
      m.positions[i] += w * (safe - m.positions[i]);
      dc.untangled += !moved[i];
      moved[i] = 1;
    }
  }
  return crossing_pairs(m, grid.voxel).size();
}

}  // namespace ms
