#include "live/compile_worker.h"

#include "gl/gl.h"  // glad before GLFW
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/clock.h"
#include "core/error.h"
#include "render/frame.h"
#include "shader/assemble.h"

namespace ms::live {

CompileWorker::CompileWorker(GLFWwindow* share, const Context& ctx) : ctx_(ctx) {
  window_ = create_shared_hidden_window(share);
  blend_window_ = window_ ? create_shared_hidden_window(share) : nullptr;
  if (!blend_window_) {
    if (window_) glfwDestroyWindow(window_);
    fail_system("no GL context shared with the window for the compile worker");
  }
  thread_ = std::thread([this] { run(); });
}

CompileWorker::~CompileWorker() {
  {
    std::lock_guard<std::mutex> lock(m_);
    stop_ = true;
    queued_.reset();
  }
  cv_.notify_all();
  thread_.join();
  done_.reset();  // its programs go with the UI context current
  glfwDestroyWindow(blend_window_);
  glfwDestroyWindow(window_);
}

void CompileWorker::submit(CompileJob job) {
  {
    std::lock_guard<std::mutex> lock(m_);
    queued_ = std::move(job);
  }
  cv_.notify_all();
}

std::optional<CompileResult> CompileWorker::poll() {
  std::lock_guard<std::mutex> lock(m_);
  std::optional<CompileResult> r = std::move(done_);
  done_.reset();
  return r;
}

CompileResult CompileWorker::wait(int id) {
  std::unique_lock<std::mutex> lock(m_);
  cv_.wait(lock, [&] { return done_ && done_->id == id; });
  CompileResult r = std::move(*done_);
  done_.reset();
  return r;
}

bool CompileWorker::newer_waiting() {
  std::lock_guard<std::mutex> lock(m_);
  return queued_.has_value() || stop_;
}

void CompileWorker::run() {
  // Each context its own targets and vertex array: framebuffers and VAOs are not shared.
  glfwMakeContextCurrent(blend_window_);
  auto blend_renderer = std::make_unique<FrameRenderer>(ctx_);
  glfwMakeContextCurrent(window_);
  {
    FrameRenderer renderer(ctx_);
    for (;;) {
      CompileJob job;
      {
        std::unique_lock<std::mutex> lock(m_);
        cv_.wait(lock, [&] { return stop_ || queued_; });
        if (stop_) break;
        job = std::move(*queued_);
        queued_.reset();
      }
      CompileResult r;
      r.id = job.id;
      bool given_up = false;
      const Clock::time_point t0 = Clock::now();
      try {
        for (const ShaderSource& s : job.sources) {
          if (newer_waiting()) {
            given_up = true;
            break;
          }
          r.programs.push_back(std::make_shared<const Program>(fullscreen_vertex_source(), s));
        }
      } catch (const Error&) {
        r.error = std::current_exception();
        r.programs.clear();
      }
      if (!given_up && !r.error) build_field(job, r);
      r.gl_ms = ms_since(t0);
      const Clock::time_point t_warm = Clock::now();
      const std::shared_ptr<const Program> post =
          static_cast<int>(r.programs.size()) > job.passes ? r.programs[job.passes] : nullptr;
      if (!given_up && !r.error && post) {
        // The state of the viewer's first frame after a reload: one sample,
        // no blending, one RGBA32F target, then the post pass. Uniforms stay
        // 0 (they are not part of the variant), so the draws are cheap.
        FrameParams fp;
        fp.width = fp.height = 8;
        for (int i = 0; i < job.passes && i < static_cast<int>(r.programs.size()); ++i) {
          if (newer_waiting()) {
            given_up = true;
            break;
          }
          try {
            renderer.draw(*r.programs[i], [](const Program&) {}, *post, fp);
          } catch (const Error&) {
            // A GL error in a draw with no inputs bound is no compile error:
            // the real frame reports what it finds.
          }
        }
        glFinish();  // the programs and the driver's JIT complete before the UI thread uses them
        if (job.accumulates && !given_up && !newer_waiting()) {
          // The frames after the first: sample 1 of 2 added to sample 0, blending on.
          glfwMakeContextCurrent(blend_window_);
          bind_field(job, r);  // bindings are each context's own
          FrameParams acc = fp;
          acc.spp = 2;
          acc.sample_begin = 1;
          acc.sample_end = 2;
          for (int i = 0; i < job.passes && i < static_cast<int>(r.programs.size()); ++i) {
            try {
              blend_renderer->draw(*r.programs[i], [](const Program&) {}, *post, acc);
            } catch (const Error&) {
            }
          }
          glFinish();
          glfwMakeContextCurrent(window_);
        }
      }
      r.warm_ms = ms_since(t_warm);
      if (!given_up && !r.error && post && job.compute) {
        if (newer_waiting()) continue;  // given up
        compile_compute(job, *post, r);
      }
      if (given_up) continue;  // a newer job is waiting: nobody wants this one
      {
        std::lock_guard<std::mutex> lock(m_);
        done_ = std::move(r);
      }
      cv_.notify_all();
    }
    compute_renderer_.reset();
  }  // the renderers' objects go while this context is current
  glfwMakeContextCurrent(blend_window_);
  blend_renderer.reset();
  glfwMakeContextCurrent(nullptr);
}

void CompileWorker::build_field(const CompileJob& job, CompileResult& r) {
  try {
    if (job.graph && job.graph->plan.interpret) {
      r.field = std::make_shared<GraphField>(*job.graph);
      r.prune = r.field->prune();
    }
  } catch (const Error&) {
    r.error = std::current_exception();
    r.programs.clear();
    r.prune.reset();
    r.field.reset();
    return;
  }
  bind_field(job, r);
}

void CompileWorker::bind_field(const CompileJob& job, const CompileResult& r) {
  if (r.field) r.field->bind();
  else if (job.field) job.field->bind();
}

void CompileWorker::compile_compute(const CompileJob& job, const Program& post, CompileResult& r) {
  const Clock::time_point t0 = Clock::now();
  try {
    r.compute = std::make_shared<const Program>(Program::Compute{}, *job.compute);
  } catch (const Error& e) {
    r.compute_error = format_error(e.info());  // ComputeTrace refuses with it, as for its own compile
    return;
  }
  r.gl_ms += ms_since(t0);
  const Clock::time_point t_warm = Clock::now();
  // The viewer's first frame after a build: one sample, stored (fused) or
  // then the post pass. llvmpipe JITs the compute shader at this dispatch.
  if (!compute_renderer_) compute_renderer_ = std::make_unique<ComputeFrameRenderer>(ctx_);
  FrameParams fp;
  fp.width = fp.height = 8;
  fp.fused_post = !job.accumulates;
  try {
    compute_renderer_->draw(*r.compute, [](const Program&) {}, post, fp, job.compute_group);
  } catch (const Error&) {
    // As the fragment warm-up: no inputs bound is no compile error.
  }
  glFinish();
  r.warm_ms += ms_since(t_warm);
}

}  // namespace ms::live
