// Manifold dual contouring over a sparse field (mesh/sparse_field.h): the
// roots and normals on every sign-changing edge from the field itself, one
// vertex per surface patch of a cell (mesh/cell_table.h) at its QEF's
// minimum (mesh/qef.h), one quad per crossing edge joining the vertices
// of the four cells around it, split into two triangles. Each vertex is
// then moved onto the surface along the gradient: a crease's or corner's
// vertex, where its planes meet, is on it already and stays.
//
//   DualContour dc = dual_contour(source, sparse, progress);
//   dc.mesh;              // counter-clockwise from outside, a material per vertex
//   dc.crossings;         // points on the surface (for the Hausdorff estimate)
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/field_source.h"
#include "mesh/mesh.h"
#include "mesh/sparse_field.h"

namespace ms {

struct DualContour {
  TriMesh mesh;
  std::vector<glm::ivec3> cell;        // per vertex: its cell's first voxel
  std::vector<std::uint8_t> crease;    // per vertex: its QEF has rank 2 or 3 (on a crease or corner)
  std::vector<glm::vec3> mass;         // per vertex: its crossings' mean, world units
  std::vector<glm::vec3> crossings;    // every edge's root, world units
  std::vector<std::uint32_t> crossing_quad;  // per crossing: its first triangle (-1 if no quad)
  std::size_t cells = 0;               // cells the surface crosses
  std::size_t split_cells = 0;         // of which with more than one patch
  std::size_t missing = 0;             // crossing edges next to a skipped brick (no quad)
  std::size_t untangled = 0;           // vertices moved to undo self-intersections (mesh/untangle.h)
};

DualContour dual_contour(FieldSource& source, const SparseField& field, const MeshProgress& progress = {});

}  // namespace ms
