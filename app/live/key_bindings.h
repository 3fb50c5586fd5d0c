// Keyboard and mouse for the viewer (every binding is listed in
// docs/viewer.md and in the panel's Keys section). GLFW callbacks reach the
// ViewState through glfwSetWindowUserPointer; Dear ImGui's GLFW backend is
// installed after these and chains to them, and input ImGui wants (typing
// in a field, dragging a slider) is not also applied to the camera.
#pragma once
#include "live/view_state.h"

struct GLFWwindow;

namespace ms::live {

// Call before ImGui_ImplGlfw_InitForOpenGL(window, true).
void install_input_callbacks(GLFWwindow* window, ViewState* state);

// One key event (GLFW's key, action and mods) applied to `state`: true
// when the window should close. A shader that reads the keyboard
// (state.shader_keys) gets every key but the viewer's few; any other
// shader leaves the camera and debug-view keys idle.
bool key_event(ViewState& state, int key, int action, int mods);

// Held keys (WASD/QE fly) for this frame, `dt` seconds long.
void apply_held_keys(GLFWwindow* window, ViewState& state, double dt);

// One line per binding, for the panel and the help overlay.
const char* const* key_help();

}  // namespace ms::live
