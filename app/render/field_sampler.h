// The mesh exporter's GPU half: the scene's own map(), compiled as a
// compute pass (sdf_shaders/field_sample.glsl, assembled with
// AssembleOptions::field_sampler), evaluated on lists the host sends: the
// centres of cells, the corners of bricks, the roots on edges, and points.
// Each call is one upload, dispatches of at most kFieldChunk invocations,
// and one read-back, all counted.
//
//   Program prog(Program::Compute{}, assemble_scene(scene, opts_with_field_sampler));
//   FieldSampler fs(prog, grid, clip);          // a graph's GraphField bound first
//   std::vector<float> d = fs.cells(blocks);    // field at each block's centre
//   std::vector<float> v = fs.bricks(origins, 8);  // 9^3 corners each
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/gl.h"
#include "mesh/field_source.h"
#include "render/program.h"

namespace ms {

// The voxel grid: voxel (i, j, k) at origin + voxel * (i, j, k).
struct FieldGrid {
  glm::vec3 origin{0.0f};
  float voxel = 1.0f;
};

// Where the field is cut so that every surface closes: a sphere (a =
// centre, radius) or a box (a, b = min, max); planes: the scene's declared
// planes are solid too (cut by the same box).
struct FieldClip {
  bool sphere = false;
  glm::vec4 a{0.0f};
  glm::vec4 b{0.0f};
  bool planes = false;
};

class FieldSampler : public FieldSource {
 public:
  // mesh/field_source.h says what each call returns.
  FieldSampler(const Program& prog, const FieldGrid& grid, const FieldClip& clip, float time);
  ~FieldSampler();
  FieldSampler(const FieldSampler&) = delete;
  FieldSampler& operator=(const FieldSampler&) = delete;

  std::vector<float> cells(const std::vector<glm::ivec4>& cells) override;
  std::vector<float> bricks(const std::vector<glm::ivec3>& first_voxels, int brick) override;
  std::vector<glm::vec4> edges(const std::vector<glm::ivec4>& edges) override;
  std::vector<FieldPoint> points(const std::vector<glm::vec3>& points, bool gradient = true) override;

  // map() calls so far (each gradient is 4, each edge root up to 14), bytes read back.
  std::uint64_t evaluations() const { return evaluations_; }
  std::uint64_t readback_bytes() const { return readback_; }

 private:
  void run(int mode, std::size_t count);
  void upload(GLuint buffer, const void* data, std::size_t bytes);
  void read(GLuint buffer, void* data, std::size_t bytes);

  const Program& prog_;
  GLuint buffers_[4] = {0, 0, 0, 0};  // in, out, outV, points
  std::uint64_t evaluations_ = 0;
  std::uint64_t readback_ = 0;
};

}  // namespace ms
