#include "mesh/qef.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

namespace ms {

namespace {

// Jacobi rotations on a symmetric 3x3: a -> diagonal, v its eigenvectors (columns).
void jacobi(double a[3][3], double v[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 12; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off < 1e-30) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (std::abs(a[p][q]) < 1e-30) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a = J^T a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
}

}  // namespace

void Qef::add(const glm::dvec3& p, const glm::dvec3& n) {
  ata_[0] += n.x * n.x;
  ata_[1] += n.x * n.y;
  ata_[2] += n.x * n.z;
  ata_[3] += n.y * n.y;
  ata_[4] += n.y * n.z;
  ata_[5] += n.z * n.z;
  atb_ += n * glm::dot(n, p);
  sum_ += p;
  ++count_;
}

QefSolution Qef::solve(double cutoff) const {
  QefSolution s;
  if (count_ == 0) return s;
  const glm::dvec3 mass = sum_ / static_cast<double>(count_);
  double a[3][3] = {{ata_[0], ata_[1], ata_[2]}, {ata_[1], ata_[3], ata_[4]}, {ata_[2], ata_[4], ata_[5]}};
  // The residual at the mass point: solve A x = r about it.
  const glm::dvec3 am(a[0][0] * mass.x + a[0][1] * mass.y + a[0][2] * mass.z,
                      a[1][0] * mass.x + a[1][1] * mass.y + a[1][2] * mass.z,
                      a[2][0] * mass.x + a[2][1] * mass.y + a[2][2] * mass.z);
  const glm::dvec3 r = atb_ - am;
  double v[3][3];
  jacobi(a, v);
  const double top = std::max({std::abs(a[0][0]), std::abs(a[1][1]), std::abs(a[2][2])});
  glm::dvec3 x = mass;
  for (int k = 0; k < 3; ++k) {
    const double lambda = a[k][k];
    if (top <= 0.0 || std::abs(lambda) < cutoff * top) continue;
    const glm::dvec3 e(v[0][k], v[1][k], v[2][k]);
    x += e * (glm::dot(e, r) / lambda);
    ++s.rank;
  }
  s.point = x;
  s.mass = mass;
  return s;
}

}  // namespace ms
