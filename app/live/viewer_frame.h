// One window frame of the viewer: the scene rendered by FrameRenderer (the
// same passes as `render`, into its float targets), or traced by compute
// (--dispatch, live/compute_trace.h), blitted to the window,
// then the ImGui layer. Also the pictures taken from that frame: captures
// for --capture-dir, screenshots re-rendered at any size, window grabs.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

#include "gl/context.h"
#include "live/accumulation.h"
#include "live/compute_trace.h"
#include "live/live_log.h"
#include "live/session.h"
#include "live/view_state.h"
#include "render/bounds_check.h"
#include "render/frame.h"
#include "render/gpu_timer.h"
#include "render/uniforms.h"

namespace ms::live {

class FrameDrawer {
 public:
  // `dispatch`: what traces the scene pass (live/compute_trace.h); its
  // notes (auto's choice, a refusal) go to `log`.
  FrameDrawer(GLFWwindow* window, const Context& ctx, Session& session, ViewState& state,
              const DispatchOptions& dispatch, LiveLog& log);
  ~FrameDrawer() = default;
  FrameDrawer(const FrameDrawer&) = delete;
  FrameDrawer& operator=(const FrameDrawer&) = delete;

  // Render the scene (when a program exists), show it, run `ui` inside an
  // ImGui frame and render that. False when the window has no area.
  // A GL error while rendering is reported once, never thrown.
  bool draw(long frame, double dt, const std::function<void()>& ui);
  // Feed the GPU timer's newest result into the state's series.
  void poll_gpu_time(double now);

  // The last frame's image (post output, render size) as dir/frame_<k>.png;
  // logs "capture <k> <path>".
  void capture(const std::filesystem::path& dir, int k, LiveLog& log);
  // Re-render the current view at w x h with the scene's spp and write it,
  // the way `render` does. Throws ms::Error.
  void screenshot(const std::filesystem::path& path, int w, int h);
  // The accumulated frame as it stands (post output, render size), its
  // sample count in the file's description; logs "accumulated_shot <n> <path>".
  void save_accumulated(const std::filesystem::path& path, LiveLog& log);
  // True for the frame whose sample reached the accumulation's target.
  bool just_converged() const { return just_converged_; }
  int samples() const { return accum_.samples(); }
  // The window's back buffer with the UI (call between draw() and the swap).
  void window_shot(const std::filesystem::path& path, LiveLog& log);

  // map() on the scene's [bounds] surface as drawn now (time, sliders):
  // render/bounds_check.h, the probe's program kept in `cache`.
  BoundsCheck check_bounds(const AssembleOptions& opts, ProgramCache& cache) {
    return ms::check_bounds(posed(static_cast<float>(s_.time)), opts, uniforms(rw_, rh_), &cache);
  }

  // Home: time back to the start, iFrame to 0, every buffer to 0.
  void rewind() {
    sim_frame_ = 0;
    if (PassGraph* g = session_.graph()) g->reset();
  }

  // What traces the current program, "fragment" or "compute" (builds its
  // compute program first when it is new: the viewer logs this after a build).
  const char* dispatch() {
    sync_trace();
    return trace_.name();
  }

  // The compute program for a build's last pass, from the compile worker
  // (live/compute_trace.h wants/offer): only asked for when it would be used.
  bool wants_compute(const ShaderSource& src) const { return trace_.wants(src); }
  ComputeGroup compute_group() const { return trace_.group(); }
  void offer_compute(std::string text, std::shared_ptr<const Program> program, std::string error) {
    trace_.offer(std::move(text), std::move(program), std::move(error));
  }

  int render_width() const { return rw_; }
  int render_height() const { return rh_; }

 private:
  UniformFn uniforms(int w, int h);
  FrameInputs inputs(const Scene& posed, const UniformFn* extra) const;
  // The scene as drawn at `time`: animation applied, the interactive camera.
  Scene posed(float time) const;
  // What this frame adds to the accumulation (live/accumulation.h).
  Accumulation::Step accumulation_step(const PassGraph& graph, const Scene& view);
  // The compute program for the session's current generation, or why not.
  void sync_trace();
  // The scene pass by the current dispatch, and what it drew.
  void draw_scene(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& fp, bool step);
  Image read_color() const { return trace_.active() ? trace_.read_color() : renderer_.read_color(); }

  GLFWwindow* window_;
  const Context& ctx_;
  Session& session_;
  ViewState& s_;
  FrameRenderer renderer_;
  ComputeTrace trace_;
  LiveLog& log_;
  GpuTimer gpu_;
  long sim_frame_ = 0;       // a Shadertoy shader's iFrame: frames stepped since the last rewind
  int rw_ = 1, rh_ = 1, fbw_ = 1, fbh_ = 1;
  long frame_ = 0;
  double dt_ = 0.0;
  bool have_frame_ = false;
  Accumulation accum_;
  bool just_converged_ = false;
  Scene accum_scene_;  // the panel values the accumulation was started with
  std::string last_error_;
};

}  // namespace ms::live
