#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "mesh/mesh_check.h"

namespace ms {

namespace {

// Distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double point_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return glm::length(ap);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return glm::length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return glm::length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  const double den = 1.0 / (va + vb + vc);
  return glm::length(p - (a + ab * (vb * den) + ac * (vc * den)));
}

}  // namespace

MeshAccuracy measure_accuracy(FieldSource& source, DualContour& dc, double voxel) {
  MeshAccuracy a;
  TriMesh& m = dc.mesh;
  const std::vector<FieldPoint> at = source.points(m.positions, false);
  m.material.resize(m.positions.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const double e = std::abs(static_cast<double>(at[i].value)) / voxel;
    a.max_vertex = std::max(a.max_vertex, e);
    sum += e;
    m.material[i] = static_cast<std::uint16_t>(std::clamp(at[i].material, 0, 65535));
  }
  a.mean_vertex = at.empty() ? 0.0 : sum / static_cast<double>(at.size());
  // Mesh to surface: the field at each triangle's centroid.
  std::vector<glm::vec3> centroids(m.triangles());
  for (std::size_t t = 0; t < m.triangles(); ++t)
    centroids[t] = (m.positions[m.indices[t * 3]] + m.positions[m.indices[t * 3 + 1]] + m.positions[m.indices[t * 3 + 2]]) / 3.0f;
  for (const FieldPoint& p : source.points(centroids, false))
    a.mesh_to_surface = std::max(a.mesh_to_surface, std::abs(static_cast<double>(p.value)) / voxel);
  // Surface to mesh: each crossing to the triangles around its quad's
  // four vertices (the mesh near it; the nearest point is there or nearer).
  const MeshCorners ring = corners_of(m);
  auto tri = [&m](std::uint32_t t, const glm::dvec3& p) {
    return point_triangle(p, glm::dvec3(m.positions[m.indices[t * 3]]), glm::dvec3(m.positions[m.indices[t * 3 + 1]]),
                          glm::dvec3(m.positions[m.indices[t * 3 + 2]]));
  };
  for (std::size_t i = 0; i < dc.crossings.size(); ++i) {
    const std::uint32_t t = dc.crossing_quad[i];
    if (t == 0xffffffffu) continue;
    const glm::dvec3 p(dc.crossings[i]);
    double d = std::min(tri(t, p), tri(t + 1, p));
    for (std::uint32_t k = d > 0.01 * voxel ? t * 3 : t * 3 + 6; k < t * 3 + 6; ++k)
      for (std::uint32_t j = ring.start[m.indices[k]]; j < ring.start[m.indices[k] + 1]; ++j)
        d = std::min(d, tri(ring.tri[j], p));
    a.surface_to_mesh = std::max(a.surface_to_mesh, d / voxel);
  }
  a.hausdorff = std::max(a.mesh_to_surface, a.surface_to_mesh);
  return a;
}

}  // namespace ms
