// Shadertoy's keyboard texture from the window's keys: 256x3 texels by
// JavaScript key code (what Shadertoy indexes with: 'A' = 65, left arrow =
// 37), row 0 down, row 1 pressed this frame, row 2 toggled by each press.
//
//   on a GLFW key event:  keyboard_event(state.keys, glfw_key, action);
//   after each frame:     keyboard_frame_done(state.keys);
#pragma once
#include "render/graph.h"

namespace ms::live {

// The JavaScript key code of a GLFW key, or -1 when it has none.
int js_key_code(int glfw_key);

// action: GLFW_PRESS, GLFW_RELEASE (repeats change nothing).
void keyboard_event(KeyboardState& keys, int glfw_key, int action);

// "Pressed this frame" lasts one frame.
void keyboard_frame_done(KeyboardState& keys);

}  // namespace ms::live
