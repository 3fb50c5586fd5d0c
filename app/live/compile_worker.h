// The viewer's reload compiles, off the UI thread. A worker thread with its
// own GL context (a hidden window sharing the viewer's objects) compiles and
// links a reload's new programs, then draws each pass program once, 8x8,
// through a FrameRenderer of its own (and, for an accumulating frame, once
// blended in a second context): llvmpipe JIT-compiles a program at its
// first draw, and each context's first variant lands in Mesa's shader
// cache, so the UI thread's first real draw of the same state loads it
// instead of compiling (docs/viewer.md, "How a reload compiles").
// Meanwhile the UI thread keeps drawing the last good programs.
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
#include <thread>
#include <vector>

#include "gl/context.h"
#include "render/program.h"
#include "shader/preprocess.h"

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
};

struct CompileResult {
  int id = 0;
  std::vector<std::shared_ptr<const Program>> programs;  // one per source; empty when `error`
  std::exception_ptr error;                              // the first compile or link error (ms::Error)
  double gl_ms = 0.0;    // compile and link
  double warm_ms = 0.0;  // the warm-up draws, JIT included
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

  const Context& ctx_;
  GLFWwindow* window_ = nullptr;
  GLFWwindow* blend_window_ = nullptr;  // the second context, for the accumulating state
  std::mutex m_;
  std::condition_variable cv_;
  std::optional<CompileJob> queued_;
  std::optional<CompileResult> done_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace ms::live
