// Evaluates one verification case of the GLSL library on the GPU (llvmpipe
// in CI): a compute shader made of the library, specialized to the names
// the case uses (as a scene's shader is), and the case's expressions. It
// writes its samples to an RGBA32F texture, read back here.
//
//   GpuCase c(ctx_owner, source);           // compiles; throws ms::Error with file:line
//   std::vector<Sample> s = c.eval(points);  // f, inside, skip, check at each point
//   std::vector<glm::vec3> z = c.zeros(box, 96, 128, 3);  // the zero set along rays
#pragma once
#include <glm/vec3.hpp>

#include <string>
#include <vector>

#include "gl/gl.h"

namespace ms::test {

// What the case's GLSL provides (each a GLSL expression of `vec3 p`, or of
// `vec2 uv` for surface): see tests/library/cases.toml.
struct CaseSource {
  std::string f;             // float: the field
  std::string inside;        // bool: independent membership test ("false" when none)
  std::string skip;          // bool: points where `inside` cannot decide ("false")
  std::string check;         // float: an identity that must be ~0 ("0.0")
  std::string surface;       // vec3 of uv in [0,1]^2: the zero set of an unsigned field ("vec3(0.0)")
  std::string helpers;       // extra GLSL before the expressions
};

struct Sample {
  float f = 0.0f;
  bool inside = false;
  bool skip = false;
  float check = 0.0f;
};

struct Box {
  glm::vec3 lo{-1.0f}, hi{1.0f};
};

class GpuCase {
 public:
  // shader_dir: sdf_shaders/. Throws ms::Error on a compile or link error.
  GpuCase(const std::string& shader_dir, const CaseSource& src);
  ~GpuCase();
  GpuCase(const GpuCase&) = delete;
  GpuCase& operator=(const GpuCase&) = delete;

  std::vector<Sample> eval(const std::vector<glm::vec3>& points) const;
  // Where f changes sign along grid x grid rays parallel to each axis of the
  // box (dims 2: the two in-plane axes of z = 0, grid * grid rays each),
  // sampled at `steps` points and refined by bisection.
  std::vector<glm::vec3> zeros(const Box& box, int grid, int steps, int dims) const;
  // The surface expression on an n x n grid of uv.
  std::vector<glm::vec3> surface(int n) const;
  // The full GLSL (for failure messages).
  const std::string& text() const { return text_; }

 private:
  std::vector<float> dispatch(int mode, int count, int slots, const std::vector<glm::vec3>& points,
                              const Box& box, int grid, int steps, int dims) const;
  GLuint program_ = 0;
  std::string text_;
};

}  // namespace ms::test
