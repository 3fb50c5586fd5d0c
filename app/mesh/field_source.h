// What the mesher asks of a field: its values on lists of grid points.
// The GPU answers in render/field_sampler.h (the scene's own map()); the
// tests answer with analytic fields on the CPU. Voxel (i, j, k) sits at
// origin + voxel * (i, j, k); inside is negative.
//
//   MeshGrid grid = mesh_grid(box_min, box_max, 256);   // mesh/sparse_field.h
//   SparseField f = sample_sparse(source, grid, opts);  // only bricks near the surface
//   TriMesh m = dual_contour(source, f, &stats);        // mesh/dual_contour.h
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ms {

struct FieldPoint {
  glm::vec3 gradient{0.0f};
  float value = 0.0f;
  int material = 0;
};

class FieldSource {
 public:
  virtual ~FieldSource() = default;
  // The field at the centre of each cube (xyz: its first voxel, w: its side in voxels).
  virtual std::vector<float> cells(const std::vector<glm::ivec4>& cubes) = 0;
  // Each brick's (brick + 1)^3 corners, x fastest, brick after brick.
  virtual std::vector<float> bricks(const std::vector<glm::ivec3>& first_voxels, int brick) = 0;
  // On each edge (xyz: its first voxel, w: axis 0..2) whose ends differ in
  // sign: (unit gradient, t) at the root, t in [0, 1] from the first end.
  virtual std::vector<glm::vec4> edges(const std::vector<glm::ivec4>& edges) = 0;
  // The field, its gradient (unless !gradient: zero) and material at world points.
  virtual std::vector<FieldPoint> points(const std::vector<glm::vec3>& points, bool gradient = true) = 0;
};

// Called between steps with the stage's name and the fraction of the
// whole export done; may throw (a --timeout's deadline) to stop the work.
using MeshProgress = std::function<void(const char* stage, double fraction)>;

}  // namespace ms
