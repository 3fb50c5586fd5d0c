// The viewer's reload compiles, off the UI thread. A worker thread with its
// own GL context (a hidden window sharing the viewer's objects) compiles and
// links a reload's new programs, then draws each pass program once, 8x8,
// through a FrameRenderer of its own (and, for an accumulating frame, once
// blended in a second context): llvmpipe JIT-compiles a program at its
// first draw, and each context's first variant lands in Mesa's shader
// cache, so the UI thread's first real draw of the same state loads it
// instead of compiling (docs/viewer.md, "How a reload compiles").
// Meanwhile the UI thread keeps drawing the last good programs. Under
// --dispatch compute a job also carries the scene pass's compute source:
// compiled and dispatched once, 8x8, through a ComputeFrameRenderer of the
// worker's own (live/compute_trace.h takes the program). For an
// interpreted scene graph it builds the new node buffers and runs the
// pruning pass (render/graph_field.h) too, and binds them for the warm-up
// draws, whose map() reads them.
//
//   CompileWorker worker(window, ctx);            // UI thread, after the window
//   worker.submit({id, sources, passes});         // replaces a job not started
//   if (auto r = worker.poll()) adopt(*r);        // each frame; r->id says which
//
// Only the newest job matters: a job submitted while another compiles makes
// the worker skip the older one's remaining work, and poll() returns the
// newest finished result only. Programs are shared_ptrs: one dropped
// unadopted is deleted wherever its last owner lets go (objects are shared).
#pragma once
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "gl/context.h"
#include "render/compute_frame.h"
#include "render/graph_field.h"
#include "render/program.h"
#include "shader/assemble.h"
#include "preprocess/preprocess.h"

struct GLFWwindow;

namespace ms::live {

struct CompileJob {
  int id = 0;
  // Fragment shaders, each linked with fullscreen_vertex_source(). The
  // first `passes` are pass programs, warmed up with the post pass, which
  // is the source after them (compiled here even when the UI thread has it
  // cached: no program is ever used by both threads at once).
  std::vector<ShaderSource> sources;
  int passes = 0;
  // The frame adds samples after its first (not the one-pass frame): warm
  // that blended state too, in a second context, since each context hands
  // only its first variant of a program on through the disk shader cache.
  bool accumulates = false;
  // The last pass as compute (compute_source()), when the viewer traces it
  // with compute (wrapped with compute_group): compiled after the fragment
  // programs, warmed up once.
  std::optional<ShaderSource> compute;
  ComputeGroup compute_group;
  // A graph read anew: its prepared shape, from which the worker builds the
  // field when interpreted (its pruning pass compiled here), or else
  // `field`, the current one, which its warm-up binds (a rebuild of the same graph).
  std::shared_ptr<const GraphParts> graph;
  std::shared_ptr<const GraphField> field;
};

struct CompileResult {
  int id = 0;
  std::vector<std::shared_ptr<const Program>> programs;  // one per source; empty when `error`
  std::exception_ptr error;                              // the first compile or link error (ms::Error)
  double gl_ms = 0.0;    // compile and link (the compute program's included)
  double warm_ms = 0.0;  // the warm-up draws and dispatch, JIT included
  // The job's compute program; null when it had none, was given up or failed
  // (then compute_error: format_error() of its ms::Error, and the frame is
  // drawn with fragment, as when the UI thread's compile fails).
  std::shared_ptr<const Program> compute;
  std::string compute_error;
  // The field built from the job's graph, and its pruning pass's program.
  std::shared_ptr<GraphField> field;
  std::shared_ptr<const Program> prune;
};

class CompileWorker {
 public:
  // On the UI thread, with `ctx` (the window's) current. Throws Exit::system
  // when no shared context can be made (the viewer then compiles in line).
  CompileWorker(GLFWwindow* share, const Context& ctx);
  ~CompileWorker();  // waits for the compile in progress; UI context still current
  CompileWorker(const CompileWorker&) = delete;
  CompileWorker& operator=(const CompileWorker&) = delete;

  void submit(CompileJob job);
  std::optional<CompileResult> poll();  // the newest finished result, once
  CompileResult wait(int id);           // blocks until job `id` is done

 private:
  void run();
  bool newer_waiting();  // a job came after the one in progress: give it up
  // The job's compute program into r, dispatched once (`post`: the job's).
  void compile_compute(const CompileJob& job, const Program& post, CompileResult& r);
  // The job's graph field into r (a compile or GL error into r.error); binds
  // the field the warm-up draws read, in the current context.
  void build_field(const CompileJob& job, CompileResult& r);
  static void bind_field(const CompileJob& job, const CompileResult& r);

  const Context& ctx_;
  GLFWwindow* window_ = nullptr;
  GLFWwindow* blend_window_ = nullptr;  // the second context, for the accumulating state
  std::unique_ptr<ComputeFrameRenderer> compute_renderer_;  // window_'s, made at the first compute job
  std::mutex m_;
  std::condition_variable cv_;
  std::optional<CompileJob> queued_;
  std::optional<CompileResult> done_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace ms::live
