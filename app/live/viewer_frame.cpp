#include "live/viewer_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>

#include "gl/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "core/error.h"
#include "core/version.h"
#include "io/image_io.h"
#include "live/capture.h"
#include "render/still.h"
#include "render/uniforms.h"
#include "scene/animation.h"
#include "scene/graph_animation.h"
#include "scene/writeback.h"

namespace ms::live {
namespace fs = std::filesystem;

namespace {

void set_params(const Program& p, const std::vector<SceneParam>& params) {
  for (const SceneParam& q : params) {
    switch (q.is_int ? 0 : q.components) {  // Program::set skips one compiled out
      case 0: p.set(q.name, static_cast<int>(q.value[0])); break;
      case 1: p.set(q.name, q.value[0]); break;
      case 2: p.set(q.name, glm::make_vec2(q.value.data())); break;
      case 3: p.set(q.name, glm::make_vec3(q.value.data())); break;
      default: p.set(q.name, glm::make_vec4(q.value.data())); break;
    }
  }
}

}  // namespace

FrameDrawer::FrameDrawer(GLFWwindow* window, const Context& ctx, Session& session, ViewState& state,
                         const DispatchOptions& dispatch, LiveLog& log)
    : window_(window), ctx_(ctx), session_(session), s_(state), renderer_(ctx), trace_(ctx, dispatch), log_(log) {}

void FrameDrawer::sync_trace() {
  PassGraph* graph = session_.graph();
  const Program* post = session_.post_program();
  if (!graph || !post) return;
  const Scene view = posed(static_cast<float>(s_.time));
  std::vector<std::string> notes;
  try {
    notes = trace_.update(*graph, session_.generation(), *post, [&] {
      StillFrame f;  // auto's probe (pipeline/dispatch_probe.h) draws the scene as it stands, small
      f.in = inputs(view, nullptr);
      f.params.width = rw_;
      f.params.height = rh_;
      f.params.exposure = session_.display_exposure();
      f.params.bloom = session_.bloom();
      return f;
    });
  } catch (const Error& e) {  // auto's probe failed: this generation stays fragment (update() set it so)
    notes = {"dispatch fragment -- " + format_error(e.info())};
  }
  for (const std::string& note : notes) {
    log_.line(note);
    // A refusal is shown, never fatal: the fragment pass draws instead.
    if (note.rfind("dispatch fragment -- ", 0) == 0) {
      std::fprintf(stderr, "marchstudio: %s\n", note.c_str());
      s_.say("compute refused, drawing with fragment: " + note.substr(21), 8.0);
    }
  }
}

void FrameDrawer::draw_scene(PassGraph& graph, const Program& post, const FrameInputs& in, const FrameParams& fp,
                             bool step) {
  // map() of an interpreted graph reads these (live/session.h); auto's
  // probe in sync_trace() draws it too.
  if (const std::shared_ptr<const GraphField> field = session_.field()) field->bind();
  sync_trace();
  if (trace_.active()) trace_.draw(graph, post, in, fp, step);
  else graph.draw(renderer_, post, in, fp, step);
}

UniformFn FrameDrawer::uniforms(int w, int h) {
  // The standard uniforms come from the graph; these are the panel's sliders.
  (void)w;
  (void)h;
  return [this](const Program& p) { set_params(p, session_.params()); };
}

FrameInputs FrameDrawer::inputs(const Scene& posed, const UniformFn* extra) const {
  FrameInputs in;
  in.scene = &posed;
  in.time = static_cast<float>(s_.time);
  in.time_delta = static_cast<float>(dt_);
  in.frame = session_.shadertoy() ? static_cast<int>(sim_frame_) : static_cast<int>(frame_);
  std::copy(std::begin(s_.mouse), std::end(s_.mouse), in.mouse);
  in.keyboard = &s_.keys;
  in.extra = extra;
  return in;
}

Scene FrameDrawer::posed(float time) const {
  const Scene& scene = session_.scene();
  Scene view = scene;
  try {
    view = animated(scene, time);  // [[animation]] tracks, as `render` applies them
  } catch (const Error&) {
    // The keys make the scene unrenderable at this time (say, the camera
    // on its target): show it unanimated rather than nothing.
  }
  // Graph tracks play: the field is posed at this time (pruned again when
  // the time moved). Where a value at this time breaks the graph the field
  // holds the file's pose, and the bounds must stay those of what it draws.
  if (animates_graph(scene) && !session_.pose_graph(time)) {
    view.graph = scene.graph;
    view.bounds = scene.bounds;
    view.quality.lipschitz = scene.quality.lipschitz;
  }
  // The camera follows its animation until the user moves it (R resumes).
  const bool untouched = s_.camera.position == s_.scene_camera.position &&
                         s_.camera.target == s_.scene_camera.target && s_.camera.fov_deg == s_.scene_camera.fov_deg;
  if (!untouched) view.camera = s_.camera;
  return view;
}

Accumulation::Step FrameDrawer::accumulation_step(const PassGraph& graph, const Scene& view) {
  const Program& main = graph.program(graph.size() - 1);
  // Buffers step every frame, and a debug view's steps or a moving time
  // change the image: those never accumulate past the one sample.
  int target = s_.accumulate == ViewState::kSceneSpp ? std::max(1, session_.scene().render.spp) : s_.accumulate;
  if (graph.stateful()) target = 1;
  const bool timed = session_.shadertoy() || !view.animation.empty() || main.loc("uTime") >= 0;
  AccumulationKey key;
  key.generation = session_.generation();
  key.debug_view = session_.compiled_debug_view();
  key.width = rw_;
  key.height = rh_;
  key.camera = view.camera;
  key.time = timed ? s_.time : 0.0;
  if (main.loc("uFrame") >= 0 && !s_.paused) key.time = static_cast<double>(frame_) + 0.5;  // a new frame each time
  for (const SceneParam& p : session_.params()) key.params.insert(key.params.end(), p.value.begin(), p.value.end());
  const bool scene_changed = !scene_value_edits(accum_scene_, session_.scene()).empty();
  if (scene_changed) accum_scene_ = session_.scene();
  return accum_.next(key, scene_changed, target);
}

bool FrameDrawer::draw(long frame, double dt, const std::function<void()>& ui) {
  glfwGetFramebufferSize(window_, &fbw_, &fbh_);
  if (fbw_ <= 0 || fbh_ <= 0) return false;
  s_.fb_width = fbw_;
  s_.fb_height = fbh_;
  frame_ = frame;
  dt_ = dt;
  rw_ = std::max(1, static_cast<int>(std::lround(fbw_ * s_.render_scale)));
  rh_ = std::max(1, static_cast<int>(std::lround(fbh_ * s_.render_scale)));

  PassGraph* graph = session_.graph();
  const Program* post = session_.post_program();
  bool rendered = false;
  if (graph && post) {
    // FrameRenderer checks glGetError at its end: errors from before it
    // (none expected) must not be blamed on the scene.
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
    FrameParams fp;
    fp.width = rw_;
    fp.height = rh_;
    fp.spp = 1;  // interactive: one sample per pixel, more while nothing changes; screenshots use the scene's spp
    fp.exposure = session_.display_exposure();
    fp.bloom = session_.bloom();
    fp.fused_post = session_.fused();  // one pass straight into the result, as render at spp 1
    just_converged_ = false;
    try {
      const Scene view = posed(static_cast<float>(s_.time));
      const Accumulation::Step step = accumulation_step(*graph, view);
      if (step.draw) {
        fp.spp = step.spp;
        fp.sample_begin = step.begin;
        fp.sample_end = step.end;
        fp.open_ended = step.open_ended;
        const UniformFn extra = uniforms(rw_, rh_);
        // Paused, a shader's buffers hold still: only the image is drawn.
        gpu_.begin();
        struct EndQuery {
          GpuTimer& t;
          ~EndQuery() { t.end(); }
        } end_query{gpu_};
        draw_scene(*graph, *post, inputs(view, &extra), fp, !s_.paused);
        accum_.drawn();
        just_converged_ = accum_.converged();
        if (!s_.paused) ++sim_frame_;
      }
      s_.samples = accum_.samples();
      s_.samples_target = accum_.target();
      rendered = step.draw || have_frame_;  // converged: the buffer already holds the frame
      last_error_.clear();
    } catch (const Error& e) {
      accum_.restart();
      if (last_error_ != e.what()) std::fprintf(stderr, "marchstudio: %s\n", e.what());
      last_error_ = e.what();
    }
  }
  have_frame_ = have_frame_ || rendered;

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbw_, fbh_);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (rendered) {
    const GLuint shown = trace_.active() ? trace_.color_framebuffer() : renderer_.color_framebuffer();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, shown);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // Float to the 8-bit window: values are display-encoded already.
    glBlitFramebuffer(0, 0, rw_, rh_, 0, 0, fbw_, fbh_, GL_COLOR_BUFFER_BIT,
                      rw_ == fbw_ && rh_ == fbh_ ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  ui();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return true;
}

void FrameDrawer::poll_gpu_time(double now) {
  if (std::optional<double> ms = gpu_.poll_ms()) s_.gpu_ms.add(now, *ms);
}

void FrameDrawer::capture(const fs::path& dir, int k, LiveLog& log) {
  if (!have_frame_) {
    log.line("capture " + std::to_string(k) + " none");
    return;
  }
  try {
    std::error_code ec;
    fs::create_directories(dir, ec);
    const fs::path path = dir / ("frame_" + std::to_string(k) + ".png");
    write_image(read_color(), path, {{"Software", std::string(kSoftware) + " view"}});
    log.line("capture " + std::to_string(k) + " " + path.string());
  } catch (const Error& e) {
    log.line("capture " + std::to_string(k) + " failed -- " + e.what());
  }
}

void FrameDrawer::screenshot(const fs::path& path, int w, int h) {
  PassGraph* graph = session_.graph();
  const Program* post = session_.post_program();
  if (!graph || !post) fail_input("no program to render: the scene has not compiled yet");
  check_output_path(path);
  FrameParams fp;
  fp.width = w;
  fp.height = h;
  fp.spp = std::max(1, session_.scene().render.spp);
  fp.exposure = session_.display_exposure();
  fp.bloom = session_.bloom();
  fp.fused_post = session_.fused();  // only at spp 1 (fuse_frame())
  // A screenshot draws the frame as it stands: the buffers are not stepped
  // (they hold the window's size; a different size starts them afresh).
  const Scene view = posed(static_cast<float>(s_.time));
  const UniformFn extra = uniforms(w, h);
  draw_scene(*graph, *post, inputs(view, &extra), fp, false);
  accum_.restart();  // the frame's buffers now hold the screenshot
  Image img = read_color();
  take_flagged(img);
  write_image(img, path,
              {{"Software", std::string(kSoftware) + " view"},
               {"ImageDescription", session_.scene().name + " t=" + std::to_string(s_.time) +
                                        " spp=" + std::to_string(fp.spp) + " debug_view=" +
                                        std::to_string(session_.compiled_debug_view())}});
}

void FrameDrawer::save_accumulated(const fs::path& path, LiveLog& log) {
  if (!have_frame_) fail_input("no frame to save: the scene has not compiled yet");
  check_output_path(path);
  const int n = std::max(1, accum_.samples());
  write_image(read_color(), path,
              {{"Software", std::string(kSoftware) + " view"},
               {"ImageDescription", session_.scene().name + " t=" + std::to_string(s_.time) + " spp=" +
                                        std::to_string(n) + " accumulated debug_view=" +
                                        std::to_string(session_.compiled_debug_view())}});
  log.line("accumulated_shot " + std::to_string(n) + " " + path.string());
}

void FrameDrawer::window_shot(const fs::path& path, LiveLog& log) {
  try {
    write_image(grab_window(fbw_, fbh_), path, {{"Software", std::string(kSoftware) + " view"}});
    log.line("window_shot " + path.string());
  } catch (const Error& e) {
    log.line(std::string("window_shot failed -- ") + e.what());
  }
}

}  // namespace ms::live
