// The scene pass drawn by whichever dispatch a job chose: the
// fragment pass (FrameRenderer) or the compute dispatch (compute_frame.h),
// behind one interface, so sequences, bench, sweep and test draw with
// either without a second copy of their loops. The buffer and Cube A
// passes of a graph stay fragment passes either way.
//
//   SceneDrawer d(ctx, graph, Dispatch::compute, group);  // compiles the compute pass once
//   d.draw(graph, post, in, fp);                          // as graph.draw(renderer, post, in, fp)
//   Still s = d.read(fp.aovs);
//   auto counting = d.program(counting_src);              // fragment or compute, to match
//   d.draw_program(*counting, set_uniforms, post, fp);
//   SceneDrawer rows(ctx, Dispatch::compute);             // no graph: programs of its own only (sweep)
#pragma once
#include <memory>
#include <optional>

#include "gl/context.h"
#include "render/compute_frame.h"
#include "render/frame.h"
#include "render/graph.h"
#include "render/still.h"

namespace ms {

class SceneDrawer {
 public:
  // `d` fragment or compute (auto is resolved by the caller). Compute
  // compiles graph's last pass as a compute program; throws bad_input
  // (compute_source) for a pass that cannot run as one.
  SceneDrawer(const Context& ctx, const PassGraph& graph, Dispatch d, ComputeGroup group = {});
  // Without a graph: draw_program() only, with programs from program().
  SceneDrawer(const Context& ctx, Dispatch d, ComputeGroup group = {});
  ~SceneDrawer();
  SceneDrawer(const SceneDrawer&) = delete;
  SceneDrawer& operator=(const SceneDrawer&) = delete;

  Dispatch dispatch() const { return dispatch_; }
  // One frame that goes on from where the graph stands (PassGraph::draw).
  void draw(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& p, bool step = true);
  // A still (render/still.h draw_still): a stateful graph replays from frame 0.
  void draw_still(PassGraph& graph, const Program& post, const StillFrame& f);
  // The last draw's colour (flagged pixels counted, as render_still) and AOVs.
  Still read(bool aovs) const;
  Image read_color() const;
  Image read_aovs() const;

  // A program of its own drawn as the scene pass (bench's counting pass):
  // `src`, a scene fragment shader, compiled for this dispatch.
  std::unique_ptr<Program> program(const ShaderSource& src) const;
  void draw_program(const Program& main, const UniformFn& set_uniforms, const Program& post, const FrameParams& p);

 private:
  Dispatch dispatch_;
  ComputeGroup group_;
  std::optional<FrameRenderer> fragment_;
  std::optional<Program> compute_main_;
  std::unique_ptr<ComputeFrameRenderer> compute_;
};

}  // namespace ms
