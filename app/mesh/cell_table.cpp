#include "mesh/cell_table.h"

#include <array>
#include <numeric>

namespace ms {

namespace {

int corner_bit(const glm::ivec3& c) { return c.x | (c.y << 1) | (c.z << 2); }

int find(std::array<int, 12>& parent, int e) {
  while (parent[e] != e) e = parent[e] = parent[parent[e]];
  return e;
}

CellPatches patches_of(int mask) {
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
        // Each outside corner is cut off by a segment joining its two edges.
        for (int k = 0; k < 4; ++k)
          if (!in[k]) parent[find(parent, edges[(k + 3) % 4])] = find(parent, edges[k]);
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

const CellPatches& cell_patches(int mask) {
  static const std::array<CellPatches, 256> table = [] {
    std::array<CellPatches, 256> t;
    for (int m = 0; m < 256; ++m) t[m] = patches_of(m);
    return t;
  }();
  return table[static_cast<std::size_t>(mask & 255)];
}

}  // namespace ms
