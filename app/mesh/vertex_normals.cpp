#include "mesh/vertex_normals.h"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "mesh/mesh_check.h"

namespace ms {

namespace {

bool usable(const glm::vec3& n) {
  const float len = glm::length(n);
  return len > 0.0f && std::isfinite(len);
}

// Faces of one vertex (its corners [begin, end) in `ring`) joined when
// their normals are within kSmoothAngle, transitively: group[i] for each.
std::vector<std::uint32_t> face_groups(const MeshCorners& ring, std::uint32_t begin, std::uint32_t end,
                                       const std::vector<glm::vec3>& face) {
  const std::uint32_t n = end - begin;
  std::vector<std::uint32_t> root(n);
  std::iota(root.begin(), root.end(), 0u);
  const auto find = [&](std::uint32_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  const float near = std::cos(glm::radians(kSmoothAngle));
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const glm::vec3 a = face[ring.tri[begin + i]], b = face[ring.tri[begin + j]];
      // A face of no area has no direction: it goes with any group.
      const bool join = !usable(a) || !usable(b) || glm::dot(glm::normalize(a), glm::normalize(b)) >= near;
      if (join) root[find(j)] = find(i);
    }
  for (std::uint32_t i = 0; i < n; ++i) root[i] = find(i);
  return root;
}

}  // namespace

void vertex_normals(FieldSource& source, DualContour& dc) {
  TriMesh& m = dc.mesh;
  const std::size_t nv = m.positions.size();
  // Each face's normal scaled by twice its area (the weight of its share).
  std::vector<glm::vec3> face(m.triangles());
  for (std::size_t t = 0; t < face.size(); ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]];
    face[t] = glm::cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a);
  }
  const std::vector<FieldPoint> field = source.points(m.positions, true);
  const MeshCorners ring = corners_of(m);
  // Normal v is vertex v's (its first group's); a crease's other groups append theirs.
  m.normals.assign(nv, glm::vec3(0.0f, 0.0f, 1.0f));
  m.normal_index.assign(m.indices.size(), 0);
  std::vector<glm::vec3> sum;
  std::vector<std::uint32_t> group, slot;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::uint32_t begin = ring.start[v], end = ring.start[v + 1];
    if (dc.crease[v]) group = face_groups(ring, begin, end, face);
    else group.assign(end - begin, 0);
    if (begin == end && usable(field[v].gradient)) m.normals[v] = glm::normalize(field[v].gradient);
    sum.assign(end - begin, glm::vec3(0.0f));
    for (std::uint32_t i = 0; i < group.size(); ++i) sum[group[i]] += face[ring.tri[begin + i]];
    // Group g's normal: its faces' mean, or off a crease the gradient when
    // it points out of the faces (a kink of a bound can turn it).
    slot.assign(end - begin, 0xffffffffu);
    for (std::uint32_t i = 0; i < group.size(); ++i) {
      const std::uint32_t g = group[i];
      if (slot[g] == 0xffffffffu) {
        glm::vec3 n = sum[g];
        const glm::vec3 grad = field[v].gradient;
        if (!dc.crease[v] && usable(grad) && !(glm::dot(grad, n) < 0.0f)) n = grad;
        if (!usable(n)) n = usable(grad) ? grad : glm::vec3(0.0f, 0.0f, 1.0f);
        slot[g] = i == 0 ? v : static_cast<std::uint32_t>(m.normals.size());
        if (i != 0) m.normals.emplace_back();
        m.normals[slot[g]] = glm::normalize(n);
      }
      const std::uint32_t t = ring.tri[begin + i];
      for (int k = 0; k < 3; ++k)
        if (m.indices[3 * t + k] == v) m.normal_index[3 * t + k] = slot[g];
    }
  }
}

}  // namespace ms
