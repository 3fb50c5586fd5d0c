// The viewer's interactive state, shared by the loop (viewer.cpp), the GLFW
// callbacks (key_bindings.cpp, reached through glfwSetWindowUserPointer) and the
// ImGui panel and overlay. Keys and buttons only set requests here; the loop
// serves them between frames, so file writes and recompiles never happen
// inside a callback.
#pragma once
#include <string>

#include "live/frame_stats.h"
#include "render/graph.h"
#include "scene/scene.h"

namespace ms::live {

inline constexpr int kDebugViews = 7;  // DEBUG_VIEW 0 (lit) .. 6
const char* debug_view_name(int view);

enum class Drag { none, orbit, pan, look, shadertoy_mouse };

struct ViewState {
  Camera camera;        // what the window shows
  Camera scene_camera;  // what R goes back to: the scene file's
  double time = 0.0;    // uTime / iTime, seconds
  double start_time = 0.0;
  bool paused = false;
  float speed = 1.0f;
  int debug_view = 0;   // requested; the session compiles it
  bool show_panel = true;
  bool show_help = false;
  float render_scale = 1.0f;  // render at a fraction of the window, for slow GPUs
  bool shadertoy = false;
  bool shader_keys = false;  // the shader reads the keyboard: it takes the letter keys (live/key_bindings.h)

  // Mouse drag in progress.
  Drag drag = Drag::none;
  double last_x = 0.0, last_y = 0.0;
  float mouse[4] = {0, 0, 0, 0};  // Shadertoy iMouse, pixels, origin bottom-left
  KeyboardState keys{};           // Shadertoy's keyboard texture (live/keyboard.h)
  int fb_width = 1, fb_height = 1;
  // A panel widget is held (ImGui's active item): a drag of a folded value
  // makes its table live until it lets go (live/live_values.h).
  bool panel_dragging = false;

  // Requests, served and cleared by the loop.
  bool want_reassemble = false;   // a #define (toggle, preset, quality value) changed
  bool want_disk_reload = false;  // F5
  bool want_rewind = false;       // Home: time and iFrame to the start, buffers to 0
  bool want_shot = false;         // P: the frame, through the render capture path
  bool want_window_shot = false;  // Shift+P: the window with the UI
  bool want_accumulated_shot = false;  // K: the accumulated frame as it stands
  bool want_record_toggle = false;     // F9: start / stop recording (live/recording.h)
  int recording_frame = -1;            // the frame being recorded, for the overlay; -1: not recording
  bool want_write_camera = false; // C
  bool want_write_values = false; // Ctrl+S / panel button
  bool want_mesh = false;         // M, F8: export the mesh (live/mesh_export.h)

  // Progressive accumulation (live/accumulation.h): the samples to reach
  // while nothing changes: kSceneSpp (the scene's [render] spp), N, or
  // Accumulation::kNoLimit (0). O toggles no limit. The count is shown.
  static constexpr int kSceneSpp = -1;
  int accumulate = kSceneSpp;
  int accumulate_default = kSceneSpp;  // --accumulate: what O returns to
  int samples = 0, samples_target = 1;  // as drawn, for the overlay

  // Shown at the bottom of the window for a few seconds.
  std::string message;
  double message_until = 0.0;
  // Shown at the top while it holds (a slider can push geometry out of
  // [bounds], where it is cut off): empty when the bounds hold.
  std::string bounds_warning;

  // Frame times: GPU (timer query), CPU (our work per frame, before the
  // swap), frame (swap to swap).
  TimeSeries gpu_ms, cpu_ms, frame_ms;
  double now = 0.0;  // seconds, for the medians

  void say(const std::string& text, double seconds = 4.0) {
    message = text;
    message_until = now + seconds;
  }
};

}  // namespace ms::live
