#include "mesh/cell_table.h"

#include <array>
#include <numeric>
#include <vector>

namespace ms {

namespace {

int corner_bit(const glm::ivec3& c) { return c.x | (c.y << 1) | (c.z << 2); }

int find(std::array<int, 12>& parent, int e) {
  while (parent[e] != e) e = parent[e] = parent[parent[e]];
  return e;
}

CellPatches patches_of(int mask, int joined) {
  auto inside = [mask](const glm::ivec3& c) { return (mask >> corner_bit(c) & 1) != 0; };
  std::array<int, 12> parent;
  std::iota(parent.begin(), parent.end(), 0);
  bool crossing[12];
  for (int e = 0; e < 12; ++e) {
    glm::ivec3 b = edge_start(e);
    glm::ivec3 c = b;
    c[edge_axis(e)] = 1;
    crossing[e] = inside(b) != inside(c);
  }
  for (int f = 0; f < 3; ++f)
    for (int s = 0; s < 2; ++s) {
      const int u = (f + 1) % 3, v = (f + 2) % 3;
      // Corners around the face, and the edge from each to the next.
      const int ci[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      const int edges[4] = {edge_id(u, 0, s), edge_id(v, s, 1), edge_id(u, 1, s), edge_id(v, s, 0)};
      bool in[4];
      for (int k = 0; k < 4; ++k) {
        glm::ivec3 c(0);
        c[f] = s;
        c[u] = ci[k][0];
        c[v] = ci[k][1];
        in[k] = inside(c);
      }
      int n = 0;
      for (int k = 0; k < 4; ++k) n += crossing[edges[k]];
      if (n == 2) {
        int a = -1;
        for (int k = 0; k < 4; ++k)
          if (crossing[edges[k]]) {
            if (a < 0) a = edges[k];
            else parent[find(parent, a)] = find(parent, edges[k]);
          }
      } else if (n == 4) {
        // Each corner of the side that does not connect is cut off by a
        // segment joining its two edges.
        const bool inside_joined = (joined >> (2 * f + s) & 1) != 0;
        for (int k = 0; k < 4; ++k)
          if (in[k] != inside_joined) parent[find(parent, edges[(k + 3) % 4])] = find(parent, edges[k]);
      }
    }
  CellPatches p;
  int ids[12];
  for (int e = 0; e < 12; ++e) ids[e] = -1;
  for (int e = 0; e < 12; ++e) {
    p.patch[e] = -1;
    if (!crossing[e]) continue;
    const int r = find(parent, e);
    if (ids[r] < 0) ids[r] = p.count++;
    p.patch[e] = static_cast<std::int8_t>(ids[r]);
  }
  return p;
}

}  // namespace

glm::ivec3 edge_start(int e) {
  const int axis = edge_axis(e);
  glm::ivec3 c(0);
  c[(axis + 1) % 3] = e & 1;
  c[(axis + 2) % 3] = (e >> 1) & 1;
  return c;
}

const CellPatches& cell_patches(int mask, int joined) {
  static const std::vector<CellPatches> table = [] {
    std::vector<CellPatches> t(256 * 64);
    for (int m = 0; m < 256; ++m)
      for (int j = 0; j < 64; ++j) t[static_cast<std::size_t>(m * 64 + j)] = patches_of(m, j);
    return t;
  }();
  return table[static_cast<std::size_t>((mask & 255) * 64 + (joined & 63))];
}

void face_edges(int f, int out[4]) {
  const int axis = f / 2, side = f & 1, u = (axis + 1) % 3, v = (axis + 2) % 3;
  out[0] = edge_id(u, 0, side);
  out[1] = edge_id(v, side, 1);
  out[2] = edge_id(u, 1, side);
  out[3] = edge_id(v, side, 0);
}

glm::ivec3 face_corner(int f, int k) {
  const int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int ci[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glm::ivec3 c(0);
  c[axis] = f & 1;
  c[u] = ci[k][0];
  c[v] = ci[k][1];
  return c;
}

int ambiguous_faces(int mask) {
  static const std::array<std::uint8_t, 256> table = [] {
    std::array<std::uint8_t, 256> t{};
    for (int m = 0; m < 256; ++m)
      for (int f = 0; f < 6; ++f) {
        bool in[4];
        for (int k = 0; k < 4; ++k) in[k] = (m >> corner_bit(face_corner(f, k)) & 1) != 0;
        if (in[0] == in[2] && in[1] == in[3] && in[0] != in[1]) t[static_cast<std::size_t>(m)] |= 1 << f;
      }
    return t;
  }();
  return table[static_cast<std::size_t>(mask & 255)];
}

bool face_joined(float a, float b, float c, float d) {
  const double den = static_cast<double>(a) + c - b - d;
  const double saddle = den != 0.0 ? (static_cast<double>(a) * c - static_cast<double>(b) * d) / den : 0.0;
  // The saddle has the inside's sign: the inside diagonal connects.
  return saddle < 0.0;
}

}  // namespace ms
