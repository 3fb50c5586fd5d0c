#include "mesh/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <thread>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace ms {

MeshCorners corners_of(const TriMesh& m) {
  MeshCorners c;
  const std::size_t nv = m.positions.size();
  c.start.assign(nv + 1, 0);
  for (std::uint32_t i : m.indices) ++c.start[i + 1];
  for (std::size_t i = 0; i < nv; ++i) c.start[i + 1] += c.start[i];
  c.next.resize(m.indices.size());
  c.prev.resize(m.indices.size());
  c.tri.resize(m.indices.size());
  std::vector<std::uint32_t> fill(c.start.begin(), c.start.end() - 1);
  for (std::size_t t = 0; t < m.triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = m.indices[t * 3 + k], at = fill[v]++;
      c.next[at] = m.indices[t * 3 + (k + 1) % 3];
      c.prev[at] = m.indices[t * 3 + (k + 2) % 3];
      c.tri[at] = static_cast<std::uint32_t>(t);
    }
  return c;
}

namespace {

std::uint32_t count_next(const MeshCorners& c, std::uint32_t v, std::uint32_t n) {
  std::uint32_t k = 0;
  for (std::uint32_t i = c.start[v]; i < c.start[v + 1]; ++i) k += c.next[i] == n;
  return k;
}

// Each directed edge v -> n: once (else two neighbours disagree on the
// orientation), and n -> v once (else the edge has one face, or three or
// more). Each undirected edge counted once.
void check_edges(const MeshCorners& c, MeshCheck& out, std::size_t& edges) {
  const std::size_t nv = c.start.size() - 1;
  for (std::uint32_t v = 0; v < nv; ++v)
    for (std::uint32_t i = c.start[v]; i < c.start[v + 1]; ++i) {
      const std::uint32_t n = c.next[i];
      bool first = true;
      for (std::uint32_t j = c.start[v]; j < i && first; ++j) first = c.next[j] != n;
      if (!first) continue;
      const std::uint32_t here = count_next(c, v, n), back = count_next(c, n, v);
      if (back > 0 && n < v) continue;  // counted from n
      ++edges;
      out.flipped_edges += here > 1 || back > 1;
      if (here + back == 1) ++out.boundary_edges;
      if (here + back > 2) ++out.nonmanifold_edges;
    }
}

// A vertex is manifold when its link (each triangle's edge opposite it,
// next -> prev) is one cycle through all its triangles: one fan.
void check_fans(const MeshCorners& c, MeshCheck& out) {
  const std::size_t nv = c.start.size() - 1;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::uint32_t b = c.start[v], e = c.start[v + 1];
    if (b == e) continue;
    std::uint32_t at = b, steps = 0;
    do {
      std::uint32_t following = e;
      for (std::uint32_t j = b; j < e && following == e; ++j)
        if (c.next[j] == c.prev[at]) following = j;
      if (following == e) break;
      at = following;
      ++steps;
    } while (at != b && steps <= e - b);
    out.nonmanifold_vertices += !(at == b && steps == e - b);
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
  // Each triangle wholly on one side of the other's plane: apart (the
  // first test of Moller 1997, which settles nearly every pair).
  auto one_side = [](const glm::dvec3* p, const glm::dvec3* q) {
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double a = glm::dot(n, q[0] - p[0]), b = glm::dot(n, q[1] - p[0]), c = glm::dot(n, q[2] - p[0]);
    return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
  };
  if (one_side(A, B) || one_side(B, A)) return false;
  for (int k = 0; k < 3; ++k) {
    if (segment_crosses(A[k], A[(k + 1) % 3], B[0], B[1], B[2])) return true;
    if (segment_crosses(B[k], B[(k + 1) % 3], A[0], A[1], A[2])) return true;
  }
  return false;
}

// Triangles bucketed by centroid in cubes of two voxels (sorted, not
// hashed: a pass over memory in order), and each pair in neighbouring
// buckets that shares no vertex and whose boxes overlap tested, each pair
// once; the buckets split between two threads.
}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing_pairs(const TriMesh& m, double voxel) {
  const std::size_t nt = m.triangles();
  std::vector<glm::vec3> lo(nt), hi(nt);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(nt);
  auto key = [](const glm::ivec3& c) {
    return (static_cast<std::uint64_t>(c.x & 0x1fffff) << 42) | (static_cast<std::uint64_t>(c.y & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(c.z & 0x1fffff);
  };
  for (std::size_t t = 0; t < nt; ++t) {
    const glm::vec3 a = m.positions[m.indices[t * 3]], b = m.positions[m.indices[t * 3 + 1]],
                    c = m.positions[m.indices[t * 3 + 2]];
    lo[t] = glm::min(glm::min(a, b), c);
    hi[t] = glm::max(glm::max(a, b), c);
    keyed[t] = {key(glm::ivec3(glm::floor(glm::dvec3(a + b + c) / (6.0 * voxel)))), static_cast<std::uint32_t>(t)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> first;  // each bucket's first entry
  for (std::size_t i = 0; i < nt; ++i)
    if (i == 0 || keyed[i].first != keyed[i - 1].first) first.push_back(i);
  first.push_back(nt);
  // Boxes and corners in bucket order: the pair loops read them in a row.
  struct Tri {
    glm::vec3 lo, hi;
    std::uint32_t v[3];
  };
  std::vector<Tri> tri(nt);
  for (std::size_t i = 0; i < nt; ++i) {
    const std::uint32_t t = keyed[i].second;
    tri[i] = {lo[t], hi[t], {m.indices[t * 3], m.indices[t * 3 + 1], m.indices[t * 3 + 2]}};
  }
  auto bucket = [&](std::uint64_t k) {  // index into first, or -1
    std::size_t a = 0, b = first.size() - 1;
    while (a < b) {
      const std::size_t mid = (a + b) / 2;
      if (keyed[first[mid]].first < k) a = mid + 1;
      else b = mid;
    }
    return a < first.size() - 1 && keyed[first[a]].first == k ? static_cast<long>(a) : -1L;
  };
  auto test = [&](std::size_t i, std::size_t j) {
    const Tri &s = tri[i], &t = tri[j];
    if (s.hi.x < t.lo.x || s.hi.y < t.lo.y || s.hi.z < t.lo.z || t.hi.x < s.lo.x || t.hi.y < s.lo.y || t.hi.z < s.lo.z)
      return false;
    for (int a = 0; a < 3; ++a)
      if (s.v[a] == t.v[0] || s.v[a] == t.v[1] || s.v[a] == t.v[2]) return false;
    return triangles_cross(m, keyed[i].second, keyed[j].second);
  };
  using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
  auto run = [&](std::size_t from, std::size_t step, Pairs& n) {
    for (std::size_t bi = from; bi + 1 < first.size(); bi += step) {
      const std::uint64_t k = keyed[first[bi]].first;
      const glm::ivec3 c(static_cast<int>(k >> 42), static_cast<int>((k >> 21) & 0x1fffff), static_cast<int>(k & 0x1fffff));
      for (int d = 0; d < 27; ++d) {
        const long other = bucket(key(c + glm::ivec3(d % 3 - 1, (d / 3) % 3 - 1, d / 9 - 1)));
        if (other < static_cast<long>(bi)) continue;  // each pair of buckets once
        for (std::size_t i = first[bi]; i < first[bi + 1]; ++i)
          for (std::size_t j = other == static_cast<long>(bi) ? i + 1 : first[other]; j < first[other + 1]; ++j)
            if (test(i, j)) n.emplace_back(keyed[i].second, keyed[j].second);
      }
    }
  };
  Pairs n0, n1;
  std::thread other([&] { run(1, 2, n1); });
  run(0, 2, n0);
  other.join();
  n0.insert(n0.end(), n1.begin(), n1.end());
  return n0;
}

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

MeshCheck check_mesh(const TriMesh& m, double voxel, const std::size_t* crossings) {
  MeshCheck c;
  std::size_t edges = 0;
  for (std::size_t t = 0; t < m.triangles(); ++t) {
    const std::uint32_t* i = &m.indices[t * 3];
    c.degenerate += i[0] == i[1] || i[1] == i[2] || i[0] == i[2];
    const glm::dvec3 a(m.positions[i[0]]), b(m.positions[i[1]]), d(m.positions[i[2]]);
    c.volume += glm::dot(a, glm::cross(b, d)) / 6.0;
  }
  const MeshCorners corners = corners_of(m);
  check_edges(corners, c, edges);
  check_fans(corners, c);
  c.self_intersections = crossings ? *crossings : crossing_pairs(m, voxel).size();
  c.euler = static_cast<long long>(m.positions.size()) - static_cast<long long>(edges) +
            static_cast<long long>(m.triangles());
  return c;
}

}  // namespace ms
