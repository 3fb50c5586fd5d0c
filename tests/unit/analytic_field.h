// An analytic field on the CPU as a FieldSource (mesh/field_source.h),
// computed as field_sample.glsl does: edge roots by bisection, gradients by
// central differences a hundredth of a voxel wide. For the mesh tests.
//
//   Analytic src([](const glm::vec3& p) { return glm::length(p) - 1.0f; }, grid);
//   SparseField f = sample_sparse(src, grid, {});
#pragma once
#include <functional>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "mesh/field_source.h"
#include "mesh/sparse_field.h"

namespace ms::test {

using Field = std::function<float(const glm::vec3&)>;

// A FieldSource over a C++ function, computed as field_sample.glsl does.
class Analytic : public FieldSource {
 public:
  Analytic(Field f, const MeshGrid& g) : f_(std::move(f)), g_(g) {}
  glm::vec3 at(const glm::dvec3& v) const { return glm::vec3(g_.origin + g_.voxel * v); }
  std::vector<float> cells(const std::vector<glm::ivec4>& c) override {
    std::vector<float> out;
    for (const glm::ivec4& x : c) out.push_back(f_(at(glm::dvec3(glm::ivec3(x)) + 0.5 * x.w)));
    evals += c.size();
    return out;
  }
  std::vector<float> bricks(const std::vector<glm::ivec3>& first, int b) override {
    std::vector<float> out;
    for (const glm::ivec3& o : first)
      for (int z = 0; z <= b; ++z)
        for (int y = 0; y <= b; ++y)
          for (int x = 0; x <= b; ++x) out.push_back(f_(at(glm::dvec3(o + glm::ivec3(x, y, z)))));
    evals += out.size();
    return out;
  }
  std::vector<glm::vec4> edges(const std::vector<glm::ivec4>& e) override {
    std::vector<glm::vec4> out;
    for (const glm::ivec4& x : e) {
      const glm::dvec3 a{glm::ivec3(x)};
      glm::dvec3 b = a;
      b[x.w] += 1.0;
      double lo = 0.0, hi = 1.0;
      const bool in = f_(at(a)) < 0.0f;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((f_(at(a + (b - a) * mid)) < 0.0f) == in ? lo : hi) = mid;
      }
      const double t = 0.5 * (lo + hi);
      out.emplace_back(gradient(at(a + (b - a) * t)), static_cast<float>(t));
    }
    return out;
  }
  std::vector<FieldPoint> points(const std::vector<glm::vec3>& p, bool grad) override {
    std::vector<FieldPoint> out;
    for (const glm::vec3& x : p) out.push_back({grad ? gradient(x) : glm::vec3(0.0f), f_(x), 0});
    return out;
  }
  glm::vec3 gradient(const glm::vec3& p) const {
    const float h = 0.01f * static_cast<float>(g_.voxel);
    glm::vec3 g(f_(p + glm::vec3(h, 0, 0)) - f_(p - glm::vec3(h, 0, 0)), f_(p + glm::vec3(0, h, 0)) - f_(p - glm::vec3(0, h, 0)),
                f_(p + glm::vec3(0, 0, h)) - f_(p - glm::vec3(0, 0, h)));
    return g / (2.0f * h);
  }
  std::size_t evals = 0;

 private:
  Field f_;
  MeshGrid g_;
};

}  // namespace ms::test
