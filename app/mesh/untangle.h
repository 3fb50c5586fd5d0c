// Dual contouring's vertices can fold a mesh through itself where a
// feature is thinner than a cell. This finds the crossing triangles and
// walks their vertices back, in steps, towards a place where quads cannot
// cross: a cell's centre (the quads then tile the boundary of a union of
// cubes), or for a cell of several patches each patch's crossings' mean.
// The moved vertices leave the surface by up to a voxel; the export's
// accuracy report measures them after.
//
//   untangle(dc, grid.voxel);   // after dual_contour(), before measure_accuracy()
#pragma once
#include "mesh/dual_contour.h"

namespace ms {

// Returns the crossing pairs left (0 unless the last step did not undo
// them), for check_mesh() to take instead of searching again.
std::size_t untangle(DualContour& dc, const MeshGrid& grid);

}  // namespace ms
