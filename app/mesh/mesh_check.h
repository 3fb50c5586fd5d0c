// What an exported mesh is, checked on every export: closed (every edge
// has two faces), manifold (and every vertex's faces one fan), consistently
// oriented with outward normals (each directed edge once, positive volume),
// free of self-intersections; and how near the surface it lies.
//
//   MeshCheck c = check_mesh(mesh, voxel);   // c.ok(), c.summary()
//   MeshAccuracy a = measure_accuracy(source, dc, voxel);  // also fills dc.mesh.material
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/dual_contour.h"
#include "mesh/field_source.h"
#include "mesh/mesh.h"

namespace ms {

struct MeshCheck {
  std::size_t boundary_edges = 0;       // edges with one face
  std::size_t nonmanifold_edges = 0;    // edges with three or more
  std::size_t flipped_edges = 0;        // directed edges used twice: neighbours disagree on orientation
  std::size_t nonmanifold_vertices = 0; // vertices whose faces form more than one fan
  std::size_t degenerate = 0;           // triangles with a repeated vertex
  std::size_t self_intersections = 0;   // pairs of triangles, not neighbours, that cross
  long long euler = 0;                  // V - E + F: 2 per sphere-like component
  double volume = 0.0;                  // signed, world units: positive when normals point out
  bool ok() const;
  std::string summary() const;          // "closed, manifold, oriented, no self-intersections" or what failed
};

// `voxel`: the grid's cell, the scale of the self-intersection search.
// `crossings`: the count of crossing_pairs() when the caller has it
// already (untangle() ends with one), so the search is not run twice.
MeshCheck check_mesh(const TriMesh& mesh, double voxel, const std::size_t* crossings = nullptr);
// Per vertex, its corners in one flat array: in each of its triangles, the
// vertex after it and the one after that (counter-clockwise), and the triangle.
struct MeshCorners {
  std::vector<std::uint32_t> start;  // vertex -> its first corner; start[v + 1] ends them
  std::vector<std::uint32_t> next, prev, tri;
};
MeshCorners corners_of(const TriMesh& mesh);

// The pairs of triangles, not neighbours, that cross (each pair once).
std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing_pairs(const TriMesh& mesh, double voxel);

struct MeshAccuracy {
  double max_vertex = 0.0;   // largest |f(v)| over the vertices, in voxels
  double mean_vertex = 0.0;
  // Two-sided, estimated, in voxels: the larger of the mesh's distance to
  // the surface (|f| at every triangle's centroid) and the surface's to the
  // mesh (each edge crossing's distance to the quad made for it).
  double hausdorff = 0.0;
  double mesh_to_surface = 0.0, surface_to_mesh = 0.0;
};

// Evaluates the field at the final vertices (their materials come from
// the same pass, into dc.mesh.material) and at the triangles' centroids.
MeshAccuracy measure_accuracy(FieldSource& source, DualContour& dc, double voxel);

}  // namespace ms
