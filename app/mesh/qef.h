// The quadric error function of dual contouring (Ju et al. 2002): the
// point nearest, in least squares, to the tangent planes of a cell's edge
// crossings. Solved by eigen-decomposition with small eigenvalues dropped
// and the crossings' mean as the fall-back along them, so a flat patch
// puts its vertex at the mean, a crease on its line and a corner on it.
//
//   Qef q;  q.add(p, n); ...            // each crossing, in cell-local units
//   QefSolution s = q.solve();          // s.point, s.rank (1 plane, 2 crease, 3 corner)
#pragma once
#include <glm/vec3.hpp>

namespace ms {

struct QefSolution {
  glm::dvec3 point{0.0};
  glm::dvec3 mass{0.0};  // the crossings' mean
  int rank = 0;
};

class Qef {
 public:
  void add(const glm::dvec3& p, const glm::dvec3& n);
  // Eigenvalues below `cutoff` times the largest are taken as zero.
  QefSolution solve(double cutoff = 0.01) const;
  int count() const { return count_; }

 private:
  double ata_[6] = {0, 0, 0, 0, 0, 0};  // xx xy xz yy yz zz
  glm::dvec3 atb_{0.0};
  glm::dvec3 sum_{0.0};
  int count_ = 0;
};

}  // namespace ms
