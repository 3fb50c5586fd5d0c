// One frame: N jittered samples of a main program accumulated additively into
// a float buffer, then a post program (average, exposure, tone map, encode),
// read back top row first. Shared by scenes and Shadertoy shaders.
#pragma once
#include <functional>

#include "gl/context.h"
#include "io/image.h"
#include "render/program.h"

namespace ms {

struct FrameParams {
  int width = 0;
  int height = 0;
  int spp = 1;
  float exposure = 1.0f;
};

// Sets the main program's per-frame uniforms (it is bound when called).
using UniformFn = std::function<void(const Program&)>;

// Throws bad_input (key "--size") when width/height is not in 1..the GL
// limits, or the buffers would exceed a sane memory budget.
void check_frame_size(const GlInfo& info, int width, int height);

class FrameRenderer {
 public:
  explicit FrameRenderer(const Context& ctx);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Image with channels R,G,B,A (float).
  Image render(const Program& main, const UniformFn& set_uniforms, const Program& post, const FrameParams& p);

 private:
  const Context& ctx_;
  GLuint vao_ = 0;
};

}  // namespace ms
