#include "live/key_bindings.h"
#include "live/keyboard.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "live/camera.h"

namespace ms::live {
namespace {

constexpr double kTimeStep = 1.0 / 30.0;  // Left/Right: one 30 fps frame; Shift: 1 s

ViewState& state_of(GLFWwindow* w) { return *static_cast<ViewState*>(glfwGetWindowUserPointer(w)); }

bool imgui_wants_keys() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard; }
bool imgui_wants_mouse() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse; }

void on_key(GLFWwindow* w, int key, int, int action, int mods) {
  if (imgui_wants_keys()) return;
  if (key_event(state_of(w), key, action, mods)) glfwSetWindowShouldClose(w, GLFW_TRUE);
}

// A shader that reads the keyboard gets every key; of the viewer's own,
// only those outside the keys shaders read (Escape, Tab, Home, F-keys) act.
bool shader_key_event(ViewState& s, int key, int action, int mods) {
  keyboard_event(s.keys, key, action);
  if (action != GLFW_PRESS) return false;
  switch (key) {
    case GLFW_KEY_ESCAPE: return true;
    case GLFW_KEY_HOME: s.want_rewind = true; break;
    case GLFW_KEY_TAB:
    case GLFW_KEY_F1: s.show_panel = !s.show_panel; break;
    case GLFW_KEY_F2: s.paused = !s.paused; break;
    case GLFW_KEY_F5: s.want_disk_reload = true; break;
    case GLFW_KEY_F9: s.want_record_toggle = true; break;
    case GLFW_KEY_F8: s.want_mesh = true; break;  // M is the shader's: the export says why there is no mesh
    case GLFW_KEY_F12:
      if (mods & GLFW_MOD_SHIFT) s.want_window_shot = true;
      else s.want_shot = true;
      break;
    default: break;
  }
  return false;
}

// Keys that act on a scene's camera or debug view: a shader owns its camera
// and has no debug views, so for one they do nothing.
bool scene_only_key(int key, bool ctrl) {
  if (key >= GLFW_KEY_0 && key < GLFW_KEY_0 + kDebugViews) return !ctrl;
  return key == GLFW_KEY_R || key == GLFW_KEY_C || key == GLFW_KEY_V;
}

}  // namespace

bool key_event(ViewState& s, int key, int action, int mods) {
  if (s.shader_keys) return shader_key_event(s, key, action, mods);
  if (action == GLFW_RELEASE) return false;
  const bool shift = mods & GLFW_MOD_SHIFT, ctrl = mods & GLFW_MOD_CONTROL;
  const bool press = action == GLFW_PRESS;  // repeat only for stepping time
  switch (key) {
    case GLFW_KEY_LEFT:
    case GLFW_KEY_RIGHT: {
      const double step = (shift ? 1.0 : kTimeStep) * (key == GLFW_KEY_LEFT ? -1.0 : 1.0);
      s.time = std::max(std::min(0.0, s.start_time), s.time + step);  // a negative start stays reachable
      return false;
    }
    default: break;
  }
  if (!press || (s.shadertoy && scene_only_key(key, ctrl))) return false;
  if (key >= GLFW_KEY_0 && key < GLFW_KEY_0 + kDebugViews && !ctrl) {
    s.debug_view = key - GLFW_KEY_0;
    return false;
  }
  switch (key) {
    case GLFW_KEY_ESCAPE: return true;
    case GLFW_KEY_SPACE: s.paused = !s.paused; break;
    case GLFW_KEY_HOME: s.want_rewind = true; break;
    case GLFW_KEY_R: s.camera = s.scene_camera; break;
    case GLFW_KEY_C: s.want_write_camera = true; break;
    case GLFW_KEY_S:
      if (ctrl) s.want_write_values = true;
      break;
    case GLFW_KEY_V: s.debug_view = (s.debug_view + (shift ? kDebugViews - 1 : 1)) % kDebugViews; break;
    case GLFW_KEY_TAB:
    case GLFW_KEY_F1: s.show_panel = !s.show_panel; break;
    case GLFW_KEY_H: s.show_help = !s.show_help; break;
    case GLFW_KEY_F5: s.want_disk_reload = true; break;
    case GLFW_KEY_F9: s.want_record_toggle = true; break;
    case GLFW_KEY_O: s.accumulate = s.accumulate == 0 ? s.accumulate_default : 0; break;  // 0: no limit
    case GLFW_KEY_K: s.want_accumulated_shot = true; break;
    case GLFW_KEY_M:
    case GLFW_KEY_F8: s.want_mesh = true; break;
    case GLFW_KEY_P:
    case GLFW_KEY_F12:
      if (shift) s.want_window_shot = true;
      else s.want_shot = true;
      break;
    default: break;
  }
  return false;
}

namespace {

void on_button(GLFWwindow* w, int button, int action, int mods) {
  ViewState& s = state_of(w);
  if (action == GLFW_RELEASE) {
    if (s.drag == Drag::shadertoy_mouse) {  // Shadertoy: negative zw = button up
      s.mouse[2] = -std::abs(s.mouse[2]);
      s.mouse[3] = -std::abs(s.mouse[3]);
    }
    s.drag = Drag::none;
    return;
  }
  if (imgui_wants_mouse()) return;
  glfwGetCursorPos(w, &s.last_x, &s.last_y);
  const bool shift = mods & GLFW_MOD_SHIFT;
  if (s.shadertoy && button == GLFW_MOUSE_BUTTON_LEFT) {
    s.drag = Drag::shadertoy_mouse;
    int ww = 1, wh = 1;
    glfwGetWindowSize(w, &ww, &wh);
    const float x = static_cast<float>(s.last_x * s.fb_width / std::max(ww, 1));
    const float y = static_cast<float>(s.fb_height - s.last_y * s.fb_height / std::max(wh, 1));
    s.mouse[0] = s.mouse[2] = x;
    s.mouse[1] = s.mouse[3] = y;
    return;
  }
  if (button == GLFW_MOUSE_BUTTON_LEFT) s.drag = shift ? Drag::pan : Drag::orbit;
  if (button == GLFW_MOUSE_BUTTON_MIDDLE) s.drag = Drag::pan;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) s.drag = Drag::look;
}

void on_cursor(GLFWwindow* w, double x, double y) {
  ViewState& s = state_of(w);
  const float dx = static_cast<float>(x - s.last_x), dy = static_cast<float>(y - s.last_y);
  s.last_x = x;
  s.last_y = y;
  int ww = 1, wh = 1;
  glfwGetWindowSize(w, &ww, &wh);
  switch (s.drag) {
    case Drag::orbit: s.camera = orbit(s.camera, dx * kRadiansPerPixel, dy * kRadiansPerPixel); break;
    case Drag::pan: s.camera = pan(s.camera, dx, dy, wh); break;
    case Drag::look: s.camera = look(s.camera, dx * kRadiansPerPixel, -dy * kRadiansPerPixel); break;
    case Drag::shadertoy_mouse:
      s.mouse[0] = static_cast<float>(x * s.fb_width / std::max(ww, 1));
      s.mouse[1] = static_cast<float>(s.fb_height - y * s.fb_height / std::max(wh, 1));
      break;
    case Drag::none: break;
  }
}

void on_scroll(GLFWwindow* w, double, double yoff) {
  if (imgui_wants_mouse()) return;
  ViewState& s = state_of(w);
  s.camera = dolly(s.camera, static_cast<float>(yoff));
}

const char* const kHelp[] = {
    "Left drag        orbit around the target",
    "Middle / Shift+left drag   pan",
    "Right drag       look around (first person)",
    "Wheel            dolly towards / away from the target",
    "W A S D, Q E     fly forward/left/back/right, down/up (Shift: x4)",
    "R                reset to the scene's camera",
    "C                write the camera to the scene TOML",
    "Ctrl+S           write the panel's values to the scene TOML",
    "Space            pause / play time",
    "Left / Right     step time 1/30 s (Shift: 1 s); hold to scrub",
    "Home             time back to the scene's [render] time",
    "0..6, V, Shift+V debug view: lit, steps, normals, depth, AO, shadow, material",
    "P, F12           screenshot of the frame (--shot-size for larger)",
    "Shift+P          screenshot of the window with the panel",
    "O                accumulate samples without limit / up to the target",
    "K                save the accumulated frame as it stands",
    "M, F8            export the mesh as it stands: <scene>_mesh_001.obj, ...",
    "F9               start / stop recording frames at exact times (--record-dir)",
    "F5               reload everything from disk",
    "Tab, F1          show / hide the panel;  H  this help",
    "Esc              quit",
    nullptr,
};

}  // namespace

const char* const* key_help() { return kHelp; }

void install_input_callbacks(GLFWwindow* window, ViewState* state) {
  glfwSetWindowUserPointer(window, state);
  glfwSetKeyCallback(window, on_key);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetScrollCallback(window, on_scroll);
}

void apply_held_keys(GLFWwindow* w, ViewState& s, double dt) {
  if (imgui_wants_keys() || s.shadertoy) return;
  if (glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS)
    return;  // Ctrl+S writes values; it must not also fly backwards
  auto down = [&](int k) { return glfwGetKey(w, k) == GLFW_PRESS ? 1.0f : 0.0f; };
  const glm::vec3 dir(down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                      down(GLFW_KEY_W) - down(GLFW_KEY_S));
  if (dir == glm::vec3(0.0f)) return;
  // Speed follows the scene's scale: half the orbit distance per second.
  const bool fast = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  const float speed = 0.5f * std::max(distance_to_target(s.camera), 0.5f) * (fast ? 4.0f : 1.0f);
  s.camera = fly(s.camera, dir * speed * static_cast<float>(dt));
}

}  // namespace ms::live
