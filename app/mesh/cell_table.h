// A cube cell's surface patches, by which of its eight corners are inside:
// the marching-cubes polygons, found from the faces alone, so that two
// cells sharing a face always agree on it. Manifold dual contouring puts
// one vertex per patch (not per cell), which keeps the mesh a 2-manifold.
//
//   corner c: bit 0 x, bit 1 y, bit 2 z;  mask bit c: corner c inside
//   edge e = 4 axis + ob + 2 oc, its other two axes (axis+1, axis+2) at ob, oc
//   face f = 2 axis + side;  joined bit f: on that face, if ambiguous, the inside corners connect
//   const CellPatches& p = cell_patches(mask, joined);   p.patch[e]: -1, or its patch
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

namespace ms {

struct CellPatches {
  int count = 0;        // patches (0 to 4)
  std::int8_t patch[12];  // the patch each crossing edge belongs to, -1 where the edge does not cross
};

// On a face whose inside corners are diagonal to each other (ambiguous),
// `joined` says whether they connect (the surface cuts off each outside
// corner) or the outside ones do. The caller decides it from the face's
// own four values (face_joined), so both cells of a face agree.
const CellPatches& cell_patches(int mask, int joined = 0x3f);
// The faces of `mask` that are ambiguous (bit 2 axis + side).
int ambiguous_faces(int mask);
// The asymptotic decider (Nielson and Hamann 1991): on a face with values
// a, b, c, d around it, the bilinear saddle's sign says which diagonal
// connects; true when it is the inside (negative) one.
bool face_joined(float a, float b, float c, float d);
// The four edges of face `f`, from corner k to corner k + 1.
void face_edges(int f, int out[4]);
// Corner k (0..3) of face `f` in the order cell_patches walks it: (u, v) =
// (0,0), (1,0), (1,1), (0,1) with u = axis + 1, v = axis + 2.
glm::ivec3 face_corner(int f, int k);

// Edge e's first corner, as offsets from the cell's first voxel, and its axis.
glm::ivec3 edge_start(int e);
inline int edge_axis(int e) { return e / 4; }
// The edge of a cell along `axis` whose other two coordinates are at (ob, oc).
inline int edge_id(int axis, int ob, int oc) { return axis * 4 + ob + 2 * oc; }

}  // namespace ms
