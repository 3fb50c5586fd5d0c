#include "mesh/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

namespace ms {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (static_cast<std::uint64_t>(a) << 32) | b; }

// Counts per undirected edge, and directed edges seen twice.
void check_edges(const TriMesh& m, MeshCheck& c, std::size_t& edges) {
  std::unordered_map<std::uint64_t, std::uint32_t> directed;
  directed.reserve(m.indices.size() * 2);
  for (std::size_t t = 0; t < m.triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.indices[t * 3 + k], b = m.indices[t * 3 + (k + 1) % 3];
      if (++directed[edge_key(a, b)] == 2) ++c.flipped_edges;
    }
  for (const auto& [key, n] : directed) {
    const std::uint32_t a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
    const auto back = directed.find(edge_key(b, a));
    const std::uint32_t total = n + (back == directed.end() ? 0u : back->second);
    if (a > b && back != directed.end()) continue;  // counted from the other side
    ++edges;
    if (total == 1) ++c.boundary_edges;
    if (total > 2) ++c.nonmanifold_edges;
  }
}

// A vertex is manifold when its triangles, joined across shared edges
// around it, form one fan: count the fans by union-find on its corners.
void check_fans(const TriMesh& m, MeshCheck& c) {
  const std::size_t nv = m.positions.size();
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (std::uint32_t i : m.indices) ++start[i + 1];
  for (std::size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> tris(m.indices.size()), fill(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < m.indices.size(); ++k) tris[fill[m.indices[k]]++] = static_cast<std::uint32_t>(k / 3);
  std::vector<int> parent;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t b = start[v], e = start[v + 1];
    parent.resize(e - b);
    for (std::uint32_t i = 0; i < e - b; ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
    // Two triangles around v are joined when they share another vertex.
    for (std::uint32_t i = b; i < e; ++i)
      for (std::uint32_t j = i + 1; j < e; ++j) {
        int shared = 0;
        for (int x = 0; x < 3; ++x)
          for (int y = 0; y < 3; ++y) {
            const std::uint32_t p = m.indices[tris[i] * 3 + x], q = m.indices[tris[j] * 3 + y];
            shared += p == q && p != v;
          }
        if (shared > 0) parent[find(static_cast<int>(i - b))] = find(static_cast<int>(j - b));
      }
    int fans = 0;
    for (std::uint32_t i = 0; i < e - b; ++i) fans += find(static_cast<int>(i)) == static_cast<int>(i);
    c.nonmanifold_vertices += fans > 1;
  }
}

// Whether segment [p, q] crosses triangle (a, b, c) strictly inside both.
bool segment_crosses(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b,
                     const glm::dvec3& c) {
  const glm::dvec3 d = q - p, e1 = b - a, e2 = c - a;
  const glm::dvec3 h = glm::cross(d, e2);
  const double det = glm::dot(e1, h);
  if (std::abs(det) < 1e-30) return false;
  const double inv = 1.0 / det;
  const glm::dvec3 s = p - a;
  const double u = glm::dot(s, h) * inv;
  if (u <= 1e-9 || u >= 1.0 - 1e-9) return false;
  const glm::dvec3 r = glm::cross(s, e1);
  const double v = glm::dot(d, r) * inv;
  if (v <= 1e-9 || u + v >= 1.0 - 1e-9) return false;
  const double t = glm::dot(e2, r) * inv;
  return t > 1e-9 && t < 1.0 - 1e-9;
}

bool triangles_cross(const TriMesh& m, std::size_t s, std::size_t t) {
  glm::dvec3 A[3], B[3];
  for (int k = 0; k < 3; ++k) {
    A[k] = glm::dvec3(m.positions[m.indices[s * 3 + k]]);
    B[k] = glm::dvec3(m.positions[m.indices[t * 3 + k]]);
  }
  for (int k = 0; k < 3; ++k) {
    if (segment_crosses(A[k], A[(k + 1) % 3], B[0], B[1], B[2])) return true;
    if (segment_crosses(B[k], B[(k + 1) % 3], A[0], A[1], A[2])) return true;
  }
  return false;
}

// Triangles bucketed by centroid in cubes of two voxels; each pair in
// neighbouring buckets that shares no vertex and whose boxes overlap is tested.
std::size_t self_intersections(const TriMesh& m, double voxel) {
  const double cell = 2.0 * voxel;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> buckets;
  auto key = [](long long x, long long y, long long z) {
    return (static_cast<std::uint64_t>(x & 0x1fffff) << 42) | (static_cast<std::uint64_t>(y & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(z & 0x1fffff);
  };
  std::vector<glm::ivec3> where(m.triangles());
  for (std::size_t t = 0; t < m.triangles(); ++t) {
    const glm::dvec3 c = (glm::dvec3(m.positions[m.indices[t * 3]]) + glm::dvec3(m.positions[m.indices[t * 3 + 1]]) +
                          glm::dvec3(m.positions[m.indices[t * 3 + 2]])) / 3.0;
    where[t] = glm::ivec3(glm::floor(c / cell));
    buckets[key(where[t].x, where[t].y, where[t].z)].push_back(static_cast<std::uint32_t>(t));
  }
  std::size_t n = 0;
  for (std::size_t s = 0; s < m.triangles(); ++s) {
    const std::uint32_t* a = &m.indices[s * 3];
    glm::vec3 lo = glm::min(glm::min(m.positions[a[0]], m.positions[a[1]]), m.positions[a[2]]);
    glm::vec3 hi = glm::max(glm::max(m.positions[a[0]], m.positions[a[1]]), m.positions[a[2]]);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = buckets.find(key(where[s].x + dx, where[s].y + dy, where[s].z + dz));
          if (it == buckets.end()) continue;
          for (std::uint32_t t : it->second) {
            if (t <= s) continue;
            const std::uint32_t* b = &m.indices[static_cast<std::size_t>(t) * 3];
            bool shares = false;
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) shares = shares || a[i] == b[j];
            if (shares) continue;
            const glm::vec3 lo2 = glm::min(glm::min(m.positions[b[0]], m.positions[b[1]]), m.positions[b[2]]);
            const glm::vec3 hi2 = glm::max(glm::max(m.positions[b[0]], m.positions[b[1]]), m.positions[b[2]]);
            if (glm::any(glm::lessThan(hi, lo2)) || glm::any(glm::lessThan(hi2, lo))) continue;
            n += triangles_cross(m, s, t);
          }
        }
  }
  return n;
}

}  // namespace

bool MeshCheck::ok() const {
  return boundary_edges == 0 && nonmanifold_edges == 0 && flipped_edges == 0 && nonmanifold_vertices == 0 &&
         degenerate == 0 && self_intersections == 0 && volume > 0.0;
}

std::string MeshCheck::summary() const {
  if (ok()) return "closed, manifold, oriented outward, no self-intersections";
  std::string s;
  auto add = [&s](std::size_t n, const char* what) {
    if (n) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(boundary_edges, "boundary edges");
  add(nonmanifold_edges, "non-manifold edges");
  add(flipped_edges, "edges with inconsistent orientation");
  add(nonmanifold_vertices, "non-manifold vertices");
  add(degenerate, "degenerate triangles");
  add(self_intersections, "self-intersecting triangle pairs");
  if (volume <= 0.0) s += std::string(s.empty() ? "" : ", ") + "normals point inward";
  return s;
}

MeshCheck check_mesh(const TriMesh& m, double voxel) {
  MeshCheck c;
  std::size_t edges = 0;
  for (std::size_t t = 0; t < m.triangles(); ++t) {
    const std::uint32_t* i = &m.indices[t * 3];
    c.degenerate += i[0] == i[1] || i[1] == i[2] || i[0] == i[2];
    const glm::dvec3 a(m.positions[i[0]]), b(m.positions[i[1]]), d(m.positions[i[2]]);
    c.volume += glm::dot(a, glm::cross(b, d)) / 6.0;
  }
  check_edges(m, c, edges);
  check_fans(m, c);
  c.self_intersections = self_intersections(m, voxel);
  c.euler = static_cast<long long>(m.positions.size()) - static_cast<long long>(edges) +
            static_cast<long long>(m.triangles());
  return c;
}

}  // namespace ms
