// A cube cell's surface patches, by which of its eight corners are inside:
// the marching-cubes polygons, found from the faces alone, so that two
// cells sharing a face always agree on it. Manifold dual contouring puts
// one vertex per patch (not per cell), which keeps the mesh a 2-manifold.
//
//   corner c: bit 0 x, bit 1 y, bit 2 z;  mask bit c: corner c inside
//   edge e = 4 axis + ob + 2 oc, its other two axes (axis+1, axis+2) at ob, oc
//   const CellPatches& p = cell_patches(mask);   p.patch[e]: -1, or its patch
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

namespace ms {

struct CellPatches {
  int count = 0;        // patches (0 to 4)
  std::int8_t patch[12];  // the patch each crossing edge belongs to, -1 where the edge does not cross
};

// The face rule: on a face with two inside corners diagonal to each other,
// the inside corners connect (the surface cuts off each outside corner), the
// same rule on both of the face's cells.
const CellPatches& cell_patches(int mask);

// Edge e's first corner, as offsets from the cell's first voxel, and its axis.
glm::ivec3 edge_start(int e);
inline int edge_axis(int e) { return e / 4; }
// The edge of a cell along `axis` whose other two coordinates are at (ob, oc).
inline int edge_id(int axis, int ob, int oc) { return axis * 4 + ob + 2 * oc; }

}  // namespace ms
