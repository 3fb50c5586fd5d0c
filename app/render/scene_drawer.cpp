#include "render/scene_drawer.h"

#include "shader/assemble.h"  // fullscreen_vertex_source (added by H1 to unbreak the shared build)

namespace ms {

SceneDrawer::SceneDrawer(const Context& ctx, const PassGraph& graph, Dispatch d, ComputeGroup group)
    : dispatch_(d == Dispatch::compute ? Dispatch::compute : Dispatch::fragment), group_(group) {
  if (dispatch_ == Dispatch::compute) {
    compute_main_.emplace(Program::Compute{}, compute_source(graph.pass(graph.size() - 1), group_));
    compute_ = std::make_unique<ComputeFrameRenderer>(ctx);
  } else {
    fragment_.emplace(ctx);
  }
}

SceneDrawer::SceneDrawer(const Context& ctx, Dispatch d, ComputeGroup group)
    : dispatch_(d == Dispatch::compute ? Dispatch::compute : Dispatch::fragment), group_(group) {
  if (dispatch_ == Dispatch::compute) compute_ = std::make_unique<ComputeFrameRenderer>(ctx);
  else fragment_.emplace(ctx);
}

SceneDrawer::~SceneDrawer() = default;

void SceneDrawer::draw(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& p,
                       bool step) {
  if (fragment_) return graph.draw(*fragment_, post, in, p, step);
  graph.draw([&](const Program&, const UniformFn& u) { compute_->draw(*compute_main_, u, post, p, group_); }, in, p,
             step);
}

void SceneDrawer::draw_still(PassGraph& graph, const Program& post, const StillFrame& f) {
  if (fragment_) return ms::draw_still(*fragment_, graph, post, f);
  ms::draw_still(graph, f,
                 [&](const Program&, const UniformFn& u) { compute_->draw(*compute_main_, u, post, f.params, group_); });
}

Image SceneDrawer::read_color() const { return fragment_ ? fragment_->read_color() : compute_->read_color(); }
Image SceneDrawer::read_aovs() const { return fragment_ ? fragment_->read_aovs() : compute_->read_aovs(); }

Still SceneDrawer::read(bool aovs) const {
  Still out;
  out.color = read_color();
  out.flagged = take_flagged(out.color);
  if (aovs) out.aovs = read_aovs();
  return out;
}

std::unique_ptr<Program> SceneDrawer::program(const ShaderSource& src) const {
  if (fragment_) return std::make_unique<Program>(fullscreen_vertex_source(), src);
  PassSource pass;
  pass.source = src;
  return std::make_unique<Program>(Program::Compute{}, compute_source(pass, group_));
}

void SceneDrawer::draw_program(const Program& main, const UniformFn& set_uniforms, const Program& post,
                               const FrameParams& p) {
  if (fragment_) return fragment_->draw(main, set_uniforms, post, p);
  compute_->draw(main, set_uniforms, post, p, group_);
}

}  // namespace ms
