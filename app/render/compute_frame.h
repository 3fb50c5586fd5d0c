// The scene pass as a compute dispatch: the same assembled scene
// shader, wrapped by shader/compute_wrap.h, run once per sample over the
// frame tile by tile (glDispatchCompute), adding into RGBA32F images with
// imageLoad + imageStore and a memory barrier between samples; then the
// same post program as FrameRenderer's, reading the accumulation texture.
// Same shape as FrameRenderer (draw, read_color, read_aovs); the pixels
// equal its within float rounding (tests/cli/test_dispatch.cpp).
//
//   Program main(Program::Compute{}, wrap_compute(pass.source, group));
//   ComputeFrameRenderer r(ctx);
//   r.draw(main, set_uniforms, post, params);   // params as FrameRenderer's
//   Image img = r.read_color();
//   // or through the pass graph, which binds the pass's inputs:
//   graph.draw([&](const Program&, const UniformFn& u) { r.draw(main, u, post, params); }, in, params);
#pragma once
#include <memory>
#include <string>

#include "gl/context.h"
#include "io/image.h"
#include "render/frame.h"
#include "render/graph.h"
#include "render/program.h"
#include "render/still.h"
#include "shader/compute_wrap.h"

namespace ms {

// Which kind of pass draws the scene: --dispatch.
enum class Dispatch { fragment, compute, automatic };
const char* dispatch_name(Dispatch d);

// What draws a job: the dispatch, and the work group when it is compute
// (pipeline/dispatch_probe.h's auto measures both).
struct DispatchChoice {
  Dispatch dispatch = Dispatch::fragment;
  ComputeGroup group;
};

struct ComputeTargets;  // the images (compute_frame.cpp)

class ComputeFrameRenderer {
 public:
  explicit ComputeFrameRenderer(const Context& ctx);
  ~ComputeFrameRenderer();
  ComputeFrameRenderer(const ComputeFrameRenderer&) = delete;
  ComputeFrameRenderer& operator=(const ComputeFrameRenderer&) = delete;

  // As FrameRenderer::draw (bloom included), `main` being a compute
  // program from wrap_compute() with `group`.
  void draw(const Program& main, const UniformFn& set_uniforms, const Program& post, const FrameParams& p,
            ComputeGroup group = {});
  Image read_color() const;
  Image read_aovs() const;
  // The colour result's framebuffer, 0 before the first draw (the viewer blits it).
  GLuint color_framebuffer() const;

 private:
  const Context& ctx_;
  GLuint vao_ = 0;
  int width_ = 0, height_ = 0, spp_ = 1;
  bool aovs_ = false;
  std::unique_ptr<ComputeTargets> accum_, result_;
};

// `pass` as a compute shader: wrap_compute() told whether the pass samples
// a mip chain. No GL: it checks an input before a context exists.
ShaderSource compute_source(const PassSource& pass, ComputeGroup group = {});

// The compute dispatch of a graph's last pass, its program compiled once:
// stills, or the tiles of one (render/tiled_still.h), drawn with it. The
// pass is an SDF scene or a Shadertoy Image pass; a graph's buffer and
// Cube A passes stay fragment passes, their textures read by this one.
// Throws bad_input (wrap_compute) for a pass that needs derivatives.
class ComputeStill {
 public:
  ComputeStill(const Context& ctx, const PassGraph& graph, ComputeGroup group = {});
  // As render_still(); f.params may be a tile of a larger image.
  Still render(PassGraph& graph, const Program& post, const StillFrame& f);

 private:
  Program main_;
  ComputeFrameRenderer renderer_;
  ComputeGroup group_;
};

// A still of `graph` with its last pass (the scene) drawn by the compute
// dispatch: what render_still() returns with FrameRenderer. The graph binds
// that pass's texture inputs ([sky] environment) and sets its uniforms as
// for the fragment pass.
Still render_still_compute(const Context& ctx, PassGraph& graph, const Program& post, const StillFrame& f,
                           ComputeGroup group = {});
// The same for an SDF scene of one pass, `pass` (a graph made here).
Still render_still_compute(const Context& ctx, const PassSource& pass, const Program& post, const StillFrame& f,
                           ComputeGroup group = {});

}  // namespace ms
