// view --dispatch compute|auto: the viewer's scene pass traced by
// the compute dispatch (render/compute_frame.h) instead of FrameRenderer;
// the window's blit, the UI and a Shadertoy graph's buffer passes stay
// fragment passes. Built once per program generation: by the compile worker
// when the build went through it (offer(), live/compile_worker.h), else on
// the UI thread; a `dispatch compute=worker|ui` line says which. A pass compute cannot run
// (derivatives, an implicit-LOD lookup of a mipmapped input) or a compute
// program that fails to build is drawn with fragment, and update() says why;
// the viewer never exits for it.
//
//   ComputeTrace trace(ctx, opts.dispatch);
//   if (trace.wants(src)) job.compute = src;  // the worker compiles it...
//   trace.offer(src.text, result.compute, result.compute_error);  // ...and the next update() takes it
//   for (const std::string& note : trace.update(graph, session.generation(), post, probe_frame)) log(note);
//   if (trace.active()) trace.draw(graph, post, in, fp, step); else graph.draw(renderer, post, in, fp, step);
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/context.h"
#include "render/compute_frame.h"
#include "render/graph.h"
#include "render/program.h"
#include "render/still.h"

namespace ms::live {

struct DispatchOptions {
  Dispatch dispatch = Dispatch::fragment;  // --dispatch
  // auto: the cached or measured choice for this device
  // (pipeline/dispatch_probe.h), asked once a session, for the first
  // program compute can run, with its work group; -v's line on stderr says which.
  // --compute-group: the work group compute traces with, and the only one
  // auto times. Unset: auto's measured group, else 8x8.
  std::optional<ComputeGroup> group;
};

class ComputeTrace {
 public:
  ComputeTrace(const Context& ctx, DispatchOptions opts) : ctx_(ctx), opts_(std::move(opts)) {}

  // For `graph` (the session's program generation `generation`): nothing when
  // the generation is the last one seen; else compile its last pass as compute
  // when the dispatch asks for it. `frame` gives auto's probe its frame. Returns
  // lines for the log, none when there is nothing to say:
  //   "dispatch auto=compute", "dispatch fragment -- <why compute was refused>",
  //   "dispatch compute=worker group=WxH" (offered) or "dispatch compute=ui group=WxH" (compiled here).
  // An error of `choose` passes through; the generation then draws with fragment.
  std::vector<std::string> update(PassGraph& graph, int generation, const Program& post,
                                  const std::function<StillFrame()>& frame);
  // A compute source the worker should compile for the next build: the
  // dispatch is (or auto chose) compute and `src` is not the program held.
  bool wants(const ShaderSource& src) const;
  // The worker's compile of `text` (a program, or its error text), taken by
  // the next update() whose pass has that source; dropped by any other.
  void offer(std::string text, std::shared_ptr<const Program> program, std::string error);
  // This generation is traced with compute.
  bool active() const { return active_; }
  // The work group compute traces with: the given one, auto's measured one, else 8x8.
  ComputeGroup group() const { return opts_.group ? *opts_.group : chosen_ ? chosen_->group : ComputeGroup{}; }
  // What draws this generation: "compute" or "fragment".
  const char* name() const { return active_ ? "compute" : "fragment"; }

  // As SceneDrawer::draw; only while active().
  void draw(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& p, bool step);
  GLuint color_framebuffer() const { return renderer_->color_framebuffer(); }
  Image read_color() const { return renderer_->read_color(); }

 private:
  const Context& ctx_;
  DispatchOptions opts_;
  std::optional<DispatchChoice> chosen_;  // auto's answer, once asked
  int generation_ = -1;
  bool active_ = false;
  std::string text_;  // main_'s source: an unchanged pass is not compiled again
  std::shared_ptr<const Program> main_;
  struct Offer {
    std::string text, error;
    std::shared_ptr<const Program> program;
  };
  std::optional<Offer> offered_;
  std::unique_ptr<ComputeFrameRenderer> renderer_;
};

}  // namespace ms::live
