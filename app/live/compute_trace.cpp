#include "live/compute_trace.h"

#include "core/error.h"

namespace ms::live {

std::string ComputeTrace::update(PassGraph& graph, int generation, const Program& post,
                                 const std::function<StillFrame()>& frame) {
  if (generation == generation_) return {};
  generation_ = generation;
  active_ = false;
  if (opts_.dispatch == Dispatch::fragment) return {};
  const auto refused = [](const Error& e) { return "dispatch fragment -- " + format_error(e.info()); };
  ShaderSource src;
  try {
    src = compute_source(graph.pass(graph.size() - 1));
  } catch (const Error& e) {
    return refused(e);  // no probe: fragment is the only choice for this program
  }
  std::string note;
  if (opts_.dispatch == Dispatch::automatic && !chosen_) {
    chosen_ = opts_.choose ? opts_.choose(graph, post, frame(), ctx_) : Dispatch::fragment;
    note = std::string("dispatch auto=") + dispatch_name(*chosen_);
  }
  if ((opts_.dispatch == Dispatch::automatic ? *chosen_ : opts_.dispatch) != Dispatch::compute) return note;
  if (!main_ || src.text != text_) {
    main_.reset();
    text_.clear();
    try {
      main_ = std::make_unique<Program>(Program::Compute{}, src);
    } catch (const Error& e) {
      return refused(e);
    }
    text_ = src.text;
  }
  if (!renderer_) renderer_ = std::make_unique<ComputeFrameRenderer>(ctx_);
  active_ = true;
  return note;
}

void ComputeTrace::draw(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& p,
                        bool step) {
  // The graph draws the buffer passes and binds the last pass's inputs; the
  // last pass is this compute program (SceneDrawer's way).
  graph.draw([&](const Program&, const UniformFn& u) { renderer_->draw(*main_, u, post, p); }, in, p, step);
}

}  // namespace ms::live
