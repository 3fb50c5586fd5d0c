#include "mesh/dual_contour.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>

#include "mesh/cell_table.h"
#include "mesh/qef.h"

namespace ms {

namespace {

constexpr int kB = kBrick;
// How far (in voxels) a projected vertex may leave its cell.
constexpr double kCellMargin = 0.1;
// A QEF's eigenvalues below this fraction of the largest are dropped: a
// crease is kept where its planes meet at more than about 11 degrees.
constexpr double kFeatureCutoff = 0.01;

int corner_local(const glm::ivec3& l) { return SparseField::corner_index(l); }
glm::ivec3 unit(int axis) { return glm::ivec3(axis == 0, axis == 1, axis == 2); }

// Every sign-changing edge, each once: with the cell it starts from
// (its first voxel's), at that cell's index (SparseField::cell_index).
struct Edges {
  std::vector<glm::ivec4> list;           // first voxel, axis
  std::vector<std::uint8_t> inside_first;
  std::vector<std::int32_t> at;           // cell index * 3 + axis -> list index, or -1
  std::vector<glm::vec4> roots;           // per edge: unit normal, t
};

Edges find_edges(const SparseField& f) {
  Edges e;
  e.at.assign(f.bricks.size() * kBrickCells * 3, -1);
  for (std::size_t s = 0; s < f.bricks.size(); ++s) {
    if (!f.changes_sign(s)) continue;
    const float* v = f.brick_values(s);
    const glm::ivec3 first = f.bricks[s] * kB;
    for (int z = 0; z < kB; ++z)
      for (int y = 0; y < kB; ++y)
        for (int x = 0; x < kB; ++x) {
          const glm::ivec3 l(x, y, z);
          const bool in = v[corner_local(l)] < 0.0f;
          for (int a = 0; a < 3; ++a) {
            if ((v[corner_local(l + unit(a))] < 0.0f) == in) continue;
            e.at[static_cast<std::size_t>(f.cell_index(first + l)) * 3 + a] = static_cast<std::int32_t>(e.list.size());
            e.list.emplace_back(first + l, a);
            e.inside_first.push_back(in);
          }
        }
  }
  return e;
}

int edge_at(const SparseField& f, const Edges& e, const glm::ivec3& voxel, int axis) {
  const long i = f.cell_index(voxel);
  return i < 0 ? -1 : e.at[static_cast<std::size_t>(i) * 3 + axis];
}

// Per brick and cell, the first vertex of its patches (-1: no surface)
// and its patch table's key (mask * 64 + joined faces).
struct Vertices {
  std::vector<std::int32_t> first;
  std::vector<std::uint16_t> key;
};

// Which of the cell's ambiguous faces join their inside corners, by the
// asymptotic decider on the face's own values: both cells of a face agree.
int joined_faces(const float* v, const glm::ivec3& l, int mask) {
  int joined = 0x3f;
  const int amb = ambiguous_faces(mask);
  for (int f = 0; f < 6; ++f) {
    if (!(amb >> f & 1)) continue;
    float c[4];
    for (int k = 0; k < 4; ++k) c[k] = v[corner_local(l + face_corner(f, k))];
    if (!face_joined(c[0], c[1], c[2], c[3])) joined &= ~(1 << f);
  }
  return joined;
}

int cell_mask(const float* v, const glm::ivec3& l) {
  int m = 0;
  for (int c = 0; c < 8; ++c)
    if (v[corner_local(l + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1))] < 0.0f) m |= 1 << c;
  return m;
}

// One cell's vertices, one per patch, written from index `at` of dc's
// per-vertex arrays (sized already); `missing` counts crossings not found.
void cell_vertices(const SparseField& f, const Edges& e, const glm::ivec3& cell, int key, std::size_t at,
                   DualContour& dc, std::size_t& missing) {
  const CellPatches& p = cell_patches(key >> 6, key & 63);
  for (int k = 0; k < p.count; ++k) {
    Qef q;
    for (int i = 0; i < 12; ++i) {
      if (p.patch[i] != k) continue;
      const int axis = edge_axis(i);
      const int idx = edge_at(f, e, cell + edge_start(i), axis);
      if (idx < 0) {
        ++missing;
        continue;
      }
      const glm::vec4 r = e.roots[static_cast<std::size_t>(idx)];
      glm::dvec3 local(edge_start(i));
      // A root or normal that is not a number (a map() that returns NaN
      // there) puts its crossing at the edge's middle, with no plane.
      const bool finite = std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) && std::isfinite(r.w);
      local[axis] += finite ? std::clamp(static_cast<double>(r.w), 0.0, 1.0) : 0.5;
      q.add(local, finite ? glm::dvec3(r) : glm::dvec3(0.0));
    }
    // A cell with several patches: each vertex at its own crossings' mean,
    // where the patches stay apart (their QEF points may cross).
    QefSolution s = q.solve(p.count > 1 ? 2.0 : kFeatureCutoff);
    // The planes meet in a line or a point: the normals are split there.
    const int rank = p.count > 1 ? q.solve(kFeatureCutoff).rank : s.rank;
    if (!(std::isfinite(s.point.x) && std::isfinite(s.point.y) && std::isfinite(s.point.z))) s.point = glm::dvec3(0.5);
    s.point = glm::clamp(s.point, glm::dvec3(0.0), glm::dvec3(1.0));
    const std::size_t v = at + static_cast<std::size_t>(k);
    dc.mesh.positions[v] = glm::vec3(f.grid.origin + (glm::dvec3(cell) + s.point) * f.grid.voxel);
    dc.cell[v] = cell;
    dc.crease[v] = rank >= 2;
    dc.mass[v] = glm::vec3(f.grid.origin + (glm::dvec3(cell) + glm::clamp(s.mass, glm::dvec3(0.0), glm::dvec3(1.0))) *
                                               f.grid.voxel);
  }
}

// Whether all four crossing edges of face `f` belong to one patch of the
// cell: its two segments there are on the same polygon.
bool one_patch_on(int key, int f) {
  int edges[4];
  face_edges(f, edges);
  const CellPatches& p = cell_patches(key >> 6, key & 63);
  for (int k = 0; k < 4; ++k)
    if (p.patch[edges[k]] < 0 || p.patch[edges[k]] != p.patch[edges[0]]) return false;
  return true;
}

// Where both cells of an ambiguous face meet it with one patch each, their
// two vertices would be joined by two quad sides, four faces on one edge:
// that face takes the other diagonal, in both cells (the decider's rule
// is the face's own, so the two stay in agreement).
void fix_doubled_faces(const SparseField& f, Vertices& v) {
  for (std::size_t i = 0; i < v.first.size(); ++i) {
    if (v.first[i] != -2) continue;
    for (int axis = 0; axis < 3; ++axis) {
      const int face = 2 * axis + 1;
      if (!(ambiguous_faces(v.key[i] >> 6) >> face & 1)) continue;
      const long neighbour = f.cell_index(f.cell_at(i) + unit(axis));
      if (neighbour < 0) continue;
      const std::size_t j = static_cast<std::size_t>(neighbour);
      if (v.first[j] != -2 || !one_patch_on(v.key[i], face) || !one_patch_on(v.key[j], face - 1)) continue;
      v.key[i] = static_cast<std::uint16_t>(v.key[i] ^ (1 << face));
      v.key[j] = static_cast<std::uint16_t>(v.key[j] ^ (1 << (face - 1)));
    }
  }
}

Vertices place_vertices(const SparseField& f, const Edges& e, DualContour& dc) {
  Vertices v;
  v.first.assign(f.bricks.size() * kBrickCells, -1);
  v.key.assign(f.bricks.size() * kBrickCells, 0);
  // The patch tables of every cell first (-2: a cell with surface), then
  // the faces mended, then the vertices.
  for (std::size_t s = 0; s < f.bricks.size(); ++s) {
    if (!f.changes_sign(s)) continue;
    const float* vals = f.brick_values(s);
    for (int z = 0; z < kB; ++z)
      for (int y = 0; y < kB; ++y)
        for (int x = 0; x < kB; ++x) {
          const glm::ivec3 l(x, y, z);
          const int m = cell_mask(vals, l);
          if (m == 0 || m == 255) continue;
          const std::size_t i = static_cast<std::size_t>(f.cell_index(f.bricks[s] * kB + l));
          v.first[i] = -2;
          v.key[i] = static_cast<std::uint16_t>(m * 64 + joined_faces(vals, l, m));
        }
  }
  fix_doubled_faces(f, v);
  // Each cell's first vertex from the patch counts, then the QEFs solved
  // on two threads, each on its own bricks, writing its own vertices.
  std::size_t n = 0;
  for (std::size_t i = 0; i < v.first.size(); ++i) {
    if (v.first[i] != -2) continue;
    const int count = cell_patches(v.key[i] >> 6, v.key[i] & 63).count;
    v.first[i] = static_cast<std::int32_t>(n);
    n += static_cast<std::size_t>(count);
    ++dc.cells;
    dc.split_cells += count > 1;
  }
  dc.mesh.positions.resize(n);
  dc.cell.resize(n);
  dc.crease.resize(n);
  dc.mass.resize(n);
  std::size_t missing[2] = {0, 0};
  auto solve = [&](std::size_t part) {
    for (std::size_t s = part; s < f.bricks.size(); s += 2)
      for (std::size_t i = s * kBrickCells; i < (s + 1) * kBrickCells; ++i)
        if (v.first[i] >= 0)
          cell_vertices(f, e, f.cell_at(i), v.key[i], static_cast<std::size_t>(v.first[i]), dc, missing[part]);
  };
  std::thread other(solve, 1);
  solve(0);
  other.join();
  dc.missing += missing[0] + missing[1];
  return v;
}

// Every vertex onto the surface: Newton steps along the gradient, each at
// most a voxel. A vertex where a crease's or corner's planes meet reads
// zero there already and stays; one the QEF put beside a tight rounding
// (its planes' meeting point off the curved surface) moves onto it. Where
// a step made |f| larger (across a kink of a field that is only a bound),
// the vertex goes back and takes half the step next time.
void project_vertices(FieldSource& source, const SparseField& f, DualContour& dc) {
  struct Walk {
    std::size_t v;
    glm::dvec3 from;
    double value, scale;
  };
  std::vector<Walk> walks;
  for (std::size_t i = 0; i < dc.mesh.positions.size(); ++i) walks.push_back({i, glm::dvec3(dc.mesh.positions[i]), 1e30, 1.0});
  const double done = 1e-4 * f.grid.voxel;
  for (int pass = 0; pass < 8 && !walks.empty(); ++pass) {
    std::vector<glm::vec3> pts(walks.size());
    for (std::size_t k = 0; k < walks.size(); ++k) pts[k] = dc.mesh.positions[walks[k].v];
    const std::vector<FieldPoint> r = source.points(pts);
    std::vector<Walk> next;
    for (std::size_t k = 0; k < r.size(); ++k) {
      Walk w = walks[k];
      const double value = static_cast<double>(r[k].value);
      if (!std::isfinite(value)) continue;
      if (std::abs(value) > std::abs(w.value)) {  // worse: back, and half the step
        dc.mesh.positions[w.v] = glm::vec3(w.from);
        w.scale *= 0.5;
        next.push_back(w);
        continue;
      }
      if (std::abs(value) <= done) continue;
      const glm::dvec3 g(r[k].gradient);
      const double gg = glm::dot(g, g);
      if (!(gg > 1e-6)) continue;
      const glm::dvec3 step = g * (w.scale * value / gg);
      if (!(glm::length(step) <= f.grid.voxel)) continue;  // NaN too
      w.from = glm::dvec3(pts[k]);
      w.value = value;
      // Kept in its cell (and a margin): a vertex that wandered into the
      // next cell could fold its quads through their neighbours'.
      const glm::dvec3 lo = f.grid.origin + (glm::dvec3(dc.cell[w.v]) - kCellMargin) * f.grid.voxel;
      const glm::dvec3 hi = lo + (1.0 + 2.0 * kCellMargin) * f.grid.voxel;
      dc.mesh.positions[w.v] = glm::vec3(glm::clamp(w.from - step, lo, hi));
      next.push_back(w);
    }
    walks.swap(next);
  }
}

int vertex_of(const SparseField& f, const Vertices& v, const glm::ivec3& cell, int edge) {
  const long c = f.cell_index(cell);
  if (c < 0 || v.first[static_cast<std::size_t>(c)] < 0) return -1;
  const std::size_t i = static_cast<std::size_t>(c);
  const int patch = cell_patches(v.key[i] >> 6, v.key[i] & 63).patch[edge];
  return patch < 0 ? -1 : v.first[i] + patch;
}

// One quad per crossing edge, counter-clockwise from outside, split along
// the diagonal that keeps its two triangles closest to coplanar.
void make_quads(const SparseField& f, const Edges& e, const Vertices& v, DualContour& dc) {
  const int order[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  dc.crossing_quad.assign(e.list.size(), 0xffffffffu);
  auto& pos = dc.mesh.positions;
  for (std::size_t i = 0; i < e.list.size(); ++i) {
    const int a = e.list[i].w, b = (a + 1) % 3, c = (a + 2) % 3;
    const glm::ivec3 corner(e.list[i]);
    int q[4];
    bool ok = true;
    for (int k = 0; k < 4 && ok; ++k) {
      const glm::ivec3 cell = corner - unit(b) * order[k][0] - unit(c) * order[k][1];
      q[k] = vertex_of(f, v, cell, edge_id(a, order[k][0], order[k][1]));
      ok = q[k] >= 0;
    }
    if (!ok) {
      ++dc.missing;
      continue;
    }
    if (!e.inside_first[i]) std::swap(q[1], q[3]);
    auto normal = [&](int x, int y, int z) { return glm::cross(pos[y] - pos[x], pos[z] - pos[x]); };
    const float d02 = glm::dot(normal(q[0], q[1], q[2]), normal(q[0], q[2], q[3]));
    const float d13 = glm::dot(normal(q[0], q[1], q[3]), normal(q[1], q[2], q[3]));
    dc.crossing_quad[i] = static_cast<std::uint32_t>(dc.mesh.triangles());
    const int t[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
    const int u[6] = {q[0], q[1], q[3], q[1], q[2], q[3]};
    for (int k = 0; k < 6; ++k) dc.mesh.indices.push_back(static_cast<std::uint32_t>(d02 >= d13 ? t[k] : u[k]));
  }
}

}  // namespace

DualContour dual_contour(FieldSource& source, const SparseField& f, const MeshProgress& progress) {
  DualContour dc;
  Edges e = find_edges(f);
  if (progress) progress("edges", 0.3);
  e.roots = source.edges(e.list);
  dc.crossings.reserve(e.list.size());
  for (std::size_t i = 0; i < e.list.size(); ++i) {
    glm::dvec3 p(e.list[i]);
    p[e.list[i].w] += static_cast<double>(e.roots[i].w);
    dc.crossings.push_back(glm::vec3(f.grid.origin + p * f.grid.voxel));
  }
  if (progress) progress("vertices", 0.55);
  const Vertices v = place_vertices(f, e, dc);
  project_vertices(source, f, dc);
  if (progress) progress("faces", 0.7);
  make_quads(f, e, v, dc);
  return dc;
}

}  // namespace ms
