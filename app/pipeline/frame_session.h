// The frame pipeline's GL half. A FrameSession is one context and the
// programs compiled in it, kept from job to job (render's batch makes one
// session for all its jobs), and the job in hand: its FramePrograms (pass
// graph, post pass, bloom stage) and the dispatch that draws the scene.
// Every driver draws through it: render's stills and tiles, sequences,
// bench and test.
//
//   FrameSession session;
//   session.context(job.backend);                  // made by the first job
//   session.load(prepared);                        // pipeline/prepare.h
//   session.choose(job.dispatch, job.compute_group, probe, verbose);
//   Still s = session.draw(still);                 // a still: a graph with buffers replays
//   session.submit(inputs, fp);                    // the next frame, nothing read back
//   Still f = session.read(fp.aovs);
#pragma once
#include <memory>
#include <optional>

#include "gl/context.h"
#include "pipeline/bounds_report.h"
#include "pipeline/prepare.h"
#include "render/bloom.h"
#include "render/compute_frame.h"
#include "render/graph.h"
#include "render/graph_field.h"
#include "render/program_cache.h"
#include "render/scene_drawer.h"
#include "render/still.h"

namespace ms {

// One job's programs in a context: its pass graph, post pass and bloom
// stage, from `cache` where an earlier job compiled the same text, and the
// dispatch that draws its scene pass (fragment until choose()). A test
// suite keeps one per case; a session, the job in hand.
class FramePrograms {
 public:
  FramePrograms(const Context& ctx, ProgramCache& cache, const PreparedFrame& p);
  FramePrograms(const FramePrograms&) = delete;
  FramePrograms& operator=(const FramePrograms&) = delete;
  ~FramePrograms();

  // The dispatch of the scene pass: `requested` (with `group`, or 8x8), or
  // for auto the cached or measured choice on `probe` (pipeline/dispatch_probe.h).
  DispatchChoice choose(Dispatch requested, std::optional<ComputeGroup> group, const StillFrame& probe, bool verbose);

  // The one draw: a frame that goes on from where the graph stands (a
  // sequence's next, bench's timed ones); fp.bloom becomes this job's.
  void submit(const FrameInputs& in, const FrameParams& fp);
  // A still: a stateless graph draws once, one with buffers replays frames 0..N (render/still.h).
  void submit_still(const StillFrame& f);
  // The last frame's colour (flagged pixels counted) and AOVs.
  Still read(bool aovs) const;
  // submit_still(), then read().
  Still draw(const StillFrame& f);

  // A program of the caller's drawn as the scene pass, with this job's post
  // pass and bloom (bench's counting pass): `src`, a scene fragment
  // shader, compiled for this job's dispatch.
  std::unique_ptr<Program> program(const ShaderSource& src) const;
  void draw_program(const Program& main, const UniformFn& set_uniforms, const FrameParams& fp);
  // The last draw's colour as drawn (flagged pixels not yet counted) and AOVs.
  Image read_color() const;
  Image read_aovs() const;

  Dispatch dispatch() const;  // fragment or compute, as chosen
  PassGraph& graph() { return *graph_; }
  // A graph scene's node buffers and pruned grid; null for a map() scene or inline code.
  const GraphField* field() const { return field_.get(); }
  // A graph whose nodes move (scene/graph_animation.h): the field made
  // anew from this frame's shape, its buffers uploaded and pruned with the
  // pruning program it has when the text is the same. Returns the programs
  // compiled (0 but for a new pruning text).
  int reshape(const GraphParts& shape);

 private:
  FrameParams with_bloom(FrameParams fp) const;  // fp.bloom: this job's stage

  const Context& ctx_;
  std::unique_ptr<PassGraph> graph_;
  std::shared_ptr<const Program> post_;
  std::unique_ptr<BloomStage> bloom_;
  std::unique_ptr<SceneDrawer> drawer_;
  std::unique_ptr<GraphField> field_;
  std::string prune_text_;  // field_'s pruning pass, for reshape()
  void bind_field() const;  // before each draw: another job's buffers may be bound
};

class FrameSession {
 public:
  FrameSession() = default;
  FrameSession(const FrameSession&) = delete;
  FrameSession& operator=(const FrameSession&) = delete;
  ~FrameSession();

  // The session's context, made now with `backend` if it is the first; a
  // later job asking for another backend is refused (one context a batch).
  Context& context(Backend backend);
  // The context made already (an internal error when there is none).
  Context& context();
  bool has_context() const { return context_ != nullptr; }
  ProgramCache& cache() { return cache_; }
  BoundsReport& bounds() { return bounds_; }  // the [bounds] warning, once per scene of the session

  // The job in hand: its programs made (the last job's dropped).
  FramePrograms& load(const PreparedFrame& p);
  FramePrograms& job() { return *job_; }

  // The job's, as FramePrograms says.
  DispatchChoice choose(Dispatch requested, std::optional<ComputeGroup> group, const StillFrame& probe, bool verbose) {
    return job_->choose(requested, group, probe, verbose);
  }
  void submit(const FrameInputs& in, const FrameParams& fp) { job_->submit(in, fp); }
  Still read(bool aovs) const { return job_->read(aovs); }
  Still draw(const StillFrame& f) { return job_->draw(f); }
  PassGraph& graph() { return job_->graph(); }

 private:
  std::unique_ptr<Context> context_;
  Backend backend_ = Backend::automatic;
  // Declared after the context: everything below dies first, while it is current.
  ProgramCache cache_{64};
  BoundsReport bounds_;
  std::unique_ptr<FramePrograms> job_;
};

}  // namespace ms
