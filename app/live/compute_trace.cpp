#include "live/compute_trace.h"

#include "core/error.h"
#include "pipeline/dispatch_probe.h"

namespace ms::live {

std::vector<std::string> ComputeTrace::update(PassGraph& graph, int generation, const Program& post,
                                              const std::function<StillFrame()>& frame) {
  if (generation == generation_) return {};
  generation_ = generation;
  active_ = false;
  std::optional<Offer> offer = std::move(offered_);
  offered_.reset();
  if (opts_.dispatch == Dispatch::fragment) return {};
  const auto refused = [](const std::string& why) { return "dispatch fragment -- " + why; };
  ShaderSource src;
  try {
    src = compute_source(graph.pass(graph.size() - 1), group());
  } catch (const Error& e) {
    return {refused(format_error(e.info()))};  // no probe: fragment is the only choice for this program
  }
  std::vector<std::string> notes;
  if (opts_.dispatch == Dispatch::automatic && !chosen_) {
    chosen_ = choose_dispatch(Dispatch::automatic, graph, post, frame(), ctx_, opts_.group, true);
    notes.push_back(std::string("dispatch auto=") + dispatch_name(chosen_->dispatch));
    // A measured group other than the one src was wrapped with.
    if (chosen_->dispatch == Dispatch::compute) src = compute_source(graph.pass(graph.size() - 1), group());
  }
  if ((opts_.dispatch == Dispatch::automatic ? chosen_->dispatch : opts_.dispatch) != Dispatch::compute) return notes;
  if (!main_ || src.text != text_) {
    main_.reset();
    text_.clear();
    // The worker's, warmed up (live/compile_worker.h), or its compile error.
    if (offer && offer->text == src.text && (offer->program || !offer->error.empty())) {
      if (!offer->program) {
        notes.push_back(refused(offer->error));
        return notes;
      }
      main_ = std::move(offer->program);
      notes.push_back("dispatch compute=worker group=" + group_name(group()));
    } else {
      try {
        main_ = std::make_shared<const Program>(Program::Compute{}, src);
      } catch (const Error& e) {
        notes.push_back(refused(format_error(e.info())));
        return notes;
      }
      notes.push_back("dispatch compute=ui group=" + group_name(group()));
    }
    text_ = src.text;
  }
  if (!renderer_) renderer_ = std::make_unique<ComputeFrameRenderer>(ctx_);
  active_ = true;
  return notes;
}

bool ComputeTrace::wants(const ShaderSource& src) const {
  const Dispatch d = opts_.dispatch == Dispatch::automatic ? (chosen_ ? chosen_->dispatch : Dispatch::fragment)
                                                           : opts_.dispatch;
  return d == Dispatch::compute && !(main_ && src.text == text_);
}

void ComputeTrace::offer(std::string text, std::shared_ptr<const Program> program, std::string error) {
  offered_ = Offer{std::move(text), std::move(error), std::move(program)};
}

void ComputeTrace::draw(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& p,
                        bool step) {
  // The graph draws the buffer passes and binds the last pass's inputs; the
  // last pass is this compute program (SceneDrawer's way).
  graph.draw([&](const Program&, const UniformFn& u) { renderer_->draw(*main_, u, post, p, group()); }, in, p, step);
}

}  // namespace ms::live
