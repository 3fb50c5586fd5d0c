// Normals for a contoured mesh, so that smooth blends shade smooth and
// creases stay sharp: a vertex whose QEF found a crease or corner
// (DualContour::crease) gets one normal per group of its faces that meet
// at less than kSmoothAngle, each the group's area-weighted mean; any
// other vertex the field's gradient there. Run after untangle(), on the
// final positions.
//
//   untangle(dc, grid);
//   vertex_normals(source, dc);   // fills dc.mesh.normals and normal_index
#pragma once
#include "mesh/dual_contour.h"
#include "mesh/field_source.h"

namespace ms {

// Faces around a crease's vertex within this many degrees share a normal
// (Blender's auto-smooth default).
inline constexpr float kSmoothAngle = 30.0f;

void vertex_normals(FieldSource& source, DualContour& dc);

}  // namespace ms
