#include "pipeline/frame_session.h"

#include <string>

#include "core/error.h"
#include "pipeline/bloom_setup.h"
#include "pipeline/dispatch_probe.h"

namespace ms {

FramePrograms::FramePrograms(const Context& ctx, ProgramCache& cache, const PreparedFrame& p) : ctx_(ctx) {
  // Programs whose assembled text an earlier job compiled are reused: the
  // same text links to the same program.
  graph_ = std::make_unique<PassGraph>(p.in.passes, &cache);
  post_ = cache.get(fullscreen_vertex_source(), p.post_src);
  bloom_ = make_bloom_stage(p.in, p.display, p.opts, cache);  // pipeline/bloom_setup.h; null without bloom
  drawer_ = std::make_unique<SceneDrawer>(ctx, *graph_, Dispatch::fragment);
  if (p.opts.graph && p.opts.graph->plan.interpret) {
    field_ = std::make_unique<GraphField>(*p.opts.graph, nullptr, p.keep_pruned);
    prune_text_ = p.opts.graph->prune_src.text;
  }
}

int FramePrograms::reshape(const GraphParts& shape) {
  if (!field_) fail_system("internal: a graph reshaped without its field");
  if (field_->repose(shape)) return 0;  // the same grid: only where a node moved is pruned again
  const bool same = shape.prune_src.text == prune_text_;
  field_ = std::make_unique<GraphField>(shape, same ? field_->prune() : nullptr, false);
  prune_text_ = shape.prune_src.text;
  return same || !field_->prune() ? 0 : 1;
}

void FramePrograms::bind_field() const {
  if (field_) field_->bind();
}

FramePrograms::~FramePrograms() = default;

Still FramePrograms::read(bool aovs) const { return drawer_->read(aovs); }
std::unique_ptr<Program> FramePrograms::program(const ShaderSource& src) const { return drawer_->program(src); }
Image FramePrograms::read_color() const { return drawer_->read_color(); }
Image FramePrograms::read_aovs() const { return drawer_->read_aovs(); }
Dispatch FramePrograms::dispatch() const { return drawer_->dispatch(); }

DispatchChoice FramePrograms::choose(Dispatch requested, std::optional<ComputeGroup> group, const StillFrame& probe,
                                     bool verbose) {
  StillFrame f = probe;
  f.params = with_bloom(f.params);  // the probe draws the job's frame, bloom included
  bind_field();
  const DispatchChoice c = choose_dispatch(requested, *graph_, *post_, f, ctx_, group, verbose);
  if (c.dispatch == Dispatch::compute) drawer_ = std::make_unique<SceneDrawer>(ctx_, *graph_, c.dispatch, c.group);
  return c;
}

FrameParams FramePrograms::with_bloom(FrameParams fp) const {
  fp.bloom = bloom_.get();
  return fp;
}

void FramePrograms::submit(const FrameInputs& in, const FrameParams& fp) {
  bind_field();
  drawer_->draw(*graph_, *post_, in, with_bloom(fp));
}

void FramePrograms::submit_still(const StillFrame& f) {
  StillFrame g = f;
  g.params = with_bloom(f.params);
  bind_field();
  drawer_->draw_still(*graph_, *post_, g);
}

void FramePrograms::draw_program(const Program& main, const UniformFn& set_uniforms, const FrameParams& fp) {
  bind_field();
  drawer_->draw_program(main, set_uniforms, *post_, with_bloom(fp));
}

Still FramePrograms::draw(const StillFrame& f) {
  submit_still(f);
  return read(f.params.aovs);
}

FrameSession::~FrameSession() = default;

Context& FrameSession::context(Backend backend) {
  if (!context_) {
    context_ = create_headless_context(backend);
    backend_ = backend;
  } else if (backend_ != backend) {
    fail_input(std::string("a batch draws in one GL context, made with --backend ") + backend_name(backend_) +
                   "; this job asks for " + backend_name(backend),
               {}, 0, "--backend", "give every job of the batch the same --backend");
  }
  return *context_;
}

Context& FrameSession::context() {
  if (!context_) fail_system("internal: the frame session has no context yet");
  return *context_;
}

FramePrograms& FrameSession::load(const PreparedFrame& p) {
  job_.reset();
  job_ = std::make_unique<FramePrograms>(context(), cache_, p);
  return *job_;
}

}  // namespace ms
