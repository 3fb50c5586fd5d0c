#include "live/viewer.h"
#include "live/viewer_app.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "gl/gl.h"  // glad before GLFW and the ImGui backends
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "core/clock.h"
#include "core/error.h"
#include "core/format.h"
#include "gl/context.h"
#include "io/image_io.h"
#include "live/audio_out.h"
#include "live/capture.h"
#include "live/compile_worker.h"
#include "live/key_bindings.h"
#include "live/keyboard.h"
#include "live/live_log.h"
#include "live/live_values.h"
#include "live/overlay.h"
#include "live/panel.h"
#include "live/recording.h"
#include "live/session.h"
#include "live/viewer_frame.h"
#include "live/watcher.h"
#include "pipeline/input.h"
#include "render/frame.h"
#include "render/gpu_timer.h"
#include "render/tiles.h"
#include "scene/graph_scene.h"
#include "scene/load.h"
#include "scene/writeback.h"

namespace ms::live {
namespace fs = std::filesystem;

std::string fmt(const char* f, double v) { return printf_number(f, v); }

namespace {

// Dear ImGui's context and backends, torn down before the window goes.
struct ImGuiScope {
  explicit ImGuiScope(GLFWwindow* w) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // never drop an imgui.ini into the user's folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(w, true);  // chains to our callbacks (key_bindings.cpp)
    ImGui_ImplOpenGL3_Init("#version 450 core");
  }
  ~ImGuiScope() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
};

}  // namespace

void Viewer::watch_bounds(double now) {
  if (!session_.main_program() || session_.shadertoy()) return;
  // The probe assembles the files as they are now: while the worker compiles
  // a save, that is the new map, linked here on the UI thread (a stall of
  // seconds for a heavy shader). It waits for the adoption instead.
  if (compiling_.active) return;
  const bool same_params = std::equal(bounds_params_.begin(), bounds_params_.end(), session_.params().begin(),
                                      session_.params().end(),
                                      [](const SceneParam& a, const SceneParam& b) { return a.value == b.value; });
  if (session_.generation() == bounds_generation_ && same_params && now - t_bounds_ < 1.0) return;
  bounds_generation_ = session_.generation();
  bounds_params_ = session_.params();
  t_bounds_ = now;
  std::string w;
  const Scene& scene = session_.scene();
  if (scene.graph) {  // as render: a graph's box says what it may draw, no probe (nor its compile) needed
    const std::string over = scene.bounds.kind == BoundsKind::box ? graph_overhang(scene) : std::string();
    if (!over.empty())
      w = scene.file.string() + ": warning: the scene graph's box pokes out of [bounds] " + over +
          ": what lies there is cut off; grow [bounds] or delete it";
  } else {
    try {
      w = bounds_warning(scene.file.string(), drawer_->check_bounds(o_.assemble, bounds_cache_));
    } catch (const Error&) {
      return;  // the probe is the main pass's code: its reload reports the error
    }
  }
  if (w == bounds_warning_) return;
  bounds_warning_ = w;
  s_.bounds_warning = w;
  log_.line(w.empty() ? "bounds ok" : "bounds " + w);
  if (w.empty()) return;
  std::fprintf(stderr, "marchstudio: %s\n", w.c_str());  // the overlay shows it while it holds
}

// Runs after the swap of every frame: the reload line (with its latency in
// frames, loop iterations and ms), the capture, the once-a-second stats.
void Viewer::after_frame() {
  if (pending_.active) {
    pending_.active = false;
    const ReloadResult& r = pending_.result;
    const std::string latency = " frames=" + std::to_string(frames_ - pending_.frame_at_event) +
                                " iterations=" + std::to_string(iterations_ - pending_.iteration_at_event + 1) +
                                " ms=" + fmt("%.1f", (clock_seconds() - pending_.t_event) * 1e3) +
                                " compile_ms=" + fmt("%.1f", r.compile_ms) + " assemble_ms=" +
                                fmt("%.1f", r.assemble_ms) + " gl_ms=" + fmt("%.1f", r.gl_ms) +
                                " first_draw_ms=" + fmt("%.1f", pending_.first_draw_ms) +
                                " warm_ms=" + fmt("%.1f", pending_.warm_ms) +
                                " frames_during_compile=" + std::to_string(pending_.frames_during_compile);
    log_.line("reload " + std::string(r.ok ? "ok " : "failed ") + std::to_string(pending_.number) + latency +
              (r.ok ? "" : " -- " + r.error));
    if (!o_.capture_dir.empty()) drawer_->capture(o_.capture_dir, pending_.number, log_);
  }
  if (drawer_->just_converged()) {
    const int n = drawer_->samples();
    log_.line("converged " + std::to_string(n));
    if (!o_.capture_dir.empty()) {
      std::error_code ec;
      fs::create_directories(o_.capture_dir, ec);
      try {
        drawer_->save_accumulated(o_.capture_dir / ("converged_" + std::to_string(n) + ".png"), log_);
      } catch (const Error& e) {
        log_.line(std::string("accumulated_shot failed -- ") + e.what());
      }
    }
  }
}

void Viewer::serve_requests() {
  if (s_.want_shot) {
    s_.want_shot = false;
    screenshot();
  }
  if (s_.want_accumulated_shot) {
    s_.want_accumulated_shot = false;
    try {
      const fs::path path = next_free_path(o_.shot_dir, o_.input.stem().string() + "_accumulated");
      drawer_->save_accumulated(path, log_);
      s_.say("saved " + path.string() + " (" + std::to_string(drawer_->samples()) + " samples)");
    } catch (const Error& e) {
      std::fprintf(stderr, "marchstudio: %s\n", e.what());
      s_.say(std::string("not saved: ") + e.what());
    }
  }
  if (s_.want_write_camera) {
    s_.want_write_camera = false;
    write_camera();
  }
  if (s_.want_write_values) {
    s_.want_write_values = false;
    write_values();
  }
  if (s_.want_mesh) {
    s_.want_mesh = false;
    start_mesh();
  }
}

void Viewer::screenshot() {
  const int w = o_.shot_width > 0 ? o_.shot_width : drawer_->render_width();
  const int h = o_.shot_height > 0 ? o_.shot_height : drawer_->render_height();
  try {
    const fs::path path = next_free_path(o_.shot_dir, o_.input.stem().string());
    drawer_->screenshot(path, w, h);
    log_.line("screenshot " + path.string());
    s_.say("saved " + path.string());
  } catch (const Error& e) {
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    s_.say(std::string("screenshot failed: ") + e.what());
  }
}

void Viewer::write_camera() {
  if (!session_.has_toml()) return s_.say("no scene TOML to write the camera to");
  const Scene& scene = session_.scene();
  try {
    write_toml_edits(scene.file, camera_edits(s_.camera), [&](const std::string& text) {
      parse_scene(text, scene.file, {}, include_roots(scene.file, o_.assemble));
    });
    log_.line("writeback camera " + scene.file.string());
    s_.say("camera written to " + scene.file.string());
  } catch (const Error& e) {
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    s_.say(std::string("not written: ") + e.what());
  }
}

void Viewer::write_values() {
  if (!session_.has_toml()) return s_.say("no scene TOML to write to");
  const Scene& scene = session_.scene();
  const std::vector<TomlEdit> edits = scene_value_edits(session_.file_scene(), scene);
  if (edits.empty()) return s_.say("nothing changed since the file was read");
  try {
    write_toml_edits(scene.file, edits, [&](const std::string& text) {
      parse_scene(text, scene.file, {}, include_roots(scene.file, o_.assemble));
    });
    log_.line("writeback values " + std::to_string(edits.size()) + " " + scene.file.string());
    s_.say(std::to_string(edits.size()) + " values written to " + scene.file.string());
  } catch (const Error& e) {
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    s_.say(std::string("not written: ") + e.what());
  }
}

int Viewer::run() {
  const Scene first = read_input_scene(o_.input, o_.assemble, o_.set);  // bad input fails here, before any window
  int w = o_.width, h = o_.height;
  if (w <= 0 || h <= 0) {
    const double fit = std::min({1.0, 1280.0 / first.render.width, 720.0 / first.render.height});
    w = std::max(1, static_cast<int>(std::lround(first.render.width * fit)));
    h = std::max(1, static_cast<int>(std::lround(first.render.height * fit)));
  }
  // As `render` checks its size: the memory budget and a window X11 can
  // make before the window, the GL's limits once the context exists.
  constexpr int kMaxWindowSide = 16384;
  if (w > kMaxWindowSide || h > kMaxWindowSide)
    fail_input("window size " + std::to_string(w) + "x" + std::to_string(h) + " exceeds " +
                   std::to_string(kMaxWindowSide) + "x" + std::to_string(kMaxWindowSide),
               {}, 0, "--size", "render large images with `marchstudio render --size`");
  check_frame_memory(frame_memory(w, h, 2, false), w, h);
  std::unique_ptr<Context> ctx =
      create_window_context(w, h, "marchstudio view - " + o_.input.filename().string(), window_);
  check_frame_size(ctx->info(), w, h);
  // The session's programs must go before the context, also on the way out
  // of an exception.
  struct ReleaseGl {
    Session& s;
    ProgramCache& probe;
    std::unique_ptr<CompileWorker>& worker;
    ~ReleaseGl() {
      worker.reset();
      s.release_gl();
      probe.clear();
    }
  } release_gl{session_, bounds_cache_, worker_};
  try {
    worker_ = std::make_unique<CompileWorker>(window_, *ctx);
  } catch (const Error& e) {
    log_.line(std::string("compile_worker none -- ") + e.what());  // reloads compile on this thread, as before
  }
  install_input_callbacks(window_, &s_);
  ImGuiScope imgui(window_);
  FrameDrawer drawer(window_, *ctx, session_, s_, o_.dispatch, log_);
  drawer_ = &drawer;
  log_.line("start backend=glfw renderer=\"" + ctx->info().renderer + "\" size=" + std::to_string(w) + "x" +
            std::to_string(h));

  s_.show_panel = !o_.hide_panel;
  s_.paused = o_.paused;
  s_.accumulate = s_.accumulate_default = o_.accumulate;
  s_.debug_view = session_.debug_view = std::clamp(o_.debug_view, 0, kDebugViews - 1);
  session_.set_preset(o_.preset);
  session_.set_accumulate(s_.accumulate);  // the first build is already the one-pass frame where it can be
  reload(true, clock_seconds(), 0, 1, true);  // the initial build is number 0 (frame_0.png)
  s_.shadertoy = session_.shadertoy();
  s_.start_time = o_.time.value_or(session_.scene().render.time);
  s_.time = s_.start_time;

  const double t_start = clock_seconds();
  double t_last = t_start, t_stats = t_start, t_swap = t_start;
  while (!glfwWindowShouldClose(window_)) {
    ++iterations_;
    const double t0 = clock_seconds();
    glfwPollEvents();
    s_.now = t0;
    poll_files();
    adopt_compiled();
    const double dt = std::min(0.25, t0 - t_last);
    t_last = t0;
    apply_held_keys(window_, s_, dt);
    if (s_.want_rewind) {  // Home
      s_.want_rewind = false;
      s_.time = s_.start_time;
      drawer.rewind();
    }
    if (s_.want_record_toggle || (iterations_ == 1 && o_.record.first >= 0)) {  // F9, or --record A..B at start
      s_.want_record_toggle = false;
      const bool stateful = session_.graph() && session_.graph()->stateful();
      s_.say(recorder_.active() ? recorder_.stop(log_)
                                : recorder_.start(s_.time, session_.shadertoy(), stateful, log_), 6.0);
    }
    if (recorder_.active()) s_.time = recorder_.time();  // exact frame times, not the clock
    else if (!s_.paused) s_.time += dt * s_.speed;
    audio_.update(s_.time, s_.paused || recorder_.active() || s_.speed != 1.0);  // sound at 1x only
    s_.recording_frame = recorder_.active() ? recorder_.frame() : -1;

    const bool window_shot = s_.want_window_shot || (!compiling_.active && settled_ + 1 == o_.shot_frame);
    s_.want_window_shot = false;
    const double t_draw = clock_seconds();
    const bool settled = !compiling_.active;  // this frame counts for --drag and --shot-frame
    const bool scripted_drag = drag_.apply(session_.scene(), session_.params(), settled_);
    const bool drawn = drawer.draw(frames_, dt, [&] {
      if (s_.show_panel) draw_panel(s_, session_, ctx->info());
      draw_overlay(s_, session_);
      s_.panel_dragging = scripted_drag || ImGui::IsAnyItemActive();
    });
    if (drawn && pending_.active) {  // where a reload's time goes: the first draw, JIT included
      glFinish();
      pending_.first_draw_ms = (clock_seconds() - t_draw) * 1e3;
    }
    if (drawn && window_shot) drawer.window_shot(next_free_path(o_.shot_dir, o_.input.stem().string() + "_window"), log_);
    keyboard_frame_done(s_.keys);  // "pressed this frame" lasted its frame
    const double t_cpu = clock_seconds();
    glfwSwapBuffers(window_);
    const double t1 = clock_seconds();
    if (drawn) {
      ++frames_;
      s_.cpu_ms.add(t1, (t_cpu - t0) * 1e3);
      s_.frame_ms.add(t1, (t1 - t_swap) * 1e3);
      t_swap = t1;
      drawer.poll_gpu_time(t1);
      after_frame();
      watch_bounds(t1);
      const int w = o_.shot_width > 0 ? o_.shot_width : drawer.render_width();
      const int h = o_.shot_height > 0 ? o_.shot_height : drawer.render_height();
      const std::string stopped = recorder_.frame(drawer, w, h, log_);
      if (!stopped.empty()) s_.say(stopped, 6.0);
      if (settled) {
        ++settled_;
        if (settled_ == o_.shot_frame) s_.want_shot = true;
        if (settled_ == o_.mesh_frame) s_.want_mesh = true;
      }
    }
    serve_requests();
    poll_mesh();
    if (t1 - t_stats >= 1.0) {
      t_stats = t1;
      log_.line("frames " + std::to_string(frames_) + " gpu_ms=" + fmt("%.2f", s_.gpu_ms.median(t1)) +
                " cpu_ms=" + fmt("%.2f", s_.cpu_ms.median(t1)) + " frame_ms=" + fmt("%.2f", s_.frame_ms.median(t1)));
    }
    if (o_.max_frames > 0 && frames_ >= o_.max_frames) break;
    if (o_.exit_after > 0.0 && t1 - t_start >= o_.exit_after) break;
    if (!drawn) glfwWaitEventsTimeout(0.05);  // minimised: do not spin
    else if (!session_.main_program()) glfwWaitEventsTimeout(1.0 / 60.0);  // nothing to render yet: UI only
  }
  if (audio_.playing())
    log_.line("audio written " + std::to_string(audio_.written()) + " restarts " + std::to_string(audio_.restarts()));
  log_.line("exit frames=" + std::to_string(frames_));
  if (!o_.mesh_on_exit.empty()) exit_mesh_ = mesh_spec(o_.mesh_on_exit);  // the values as the window closes
  drawer_ = nullptr;
  return 0;
}

int run_viewer(const ViewerOptions& opts) {
  Viewer v(opts);
  const int code = v.run();
  return v.finish_mesh(code);  // after the window is gone: nothing left to draw while it waits
}

}  // namespace ms::live
