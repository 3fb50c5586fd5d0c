// live/key_bindings.h: which keys the viewer keeps for itself. A shader
// input that reads no keyboard (a glslViewer file, a Shadertoy JSON with no
// keyboard channel) leaves P, Shift+P and the other letter keys to the
// viewer; one that reads the keyboard gets them in its texture instead.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "live/key_bindings.h"

namespace ms::live {
namespace {

ViewState shader_state(bool reads_keyboard) {
  ViewState s;
  s.shadertoy = true;
  s.shader_keys = reads_keyboard;
  return s;
}

bool press(ViewState& s, int key, int mods = 0) { return key_event(s, key, GLFW_PRESS, mods); }

TEST(LiveKeyBindings, AShaderWithoutAKeyboardLeavesTheLettersToTheViewer) {
  ViewState s = shader_state(false);
  press(s, GLFW_KEY_P);
  EXPECT_TRUE(s.want_shot);
  EXPECT_FALSE(s.want_window_shot);
  s.want_shot = false;
  press(s, GLFW_KEY_P, GLFW_MOD_SHIFT);
  EXPECT_TRUE(s.want_window_shot);
  EXPECT_FALSE(s.want_shot);
  press(s, GLFW_KEY_SPACE);
  EXPECT_TRUE(s.paused);
  press(s, GLFW_KEY_H);
  EXPECT_TRUE(s.show_help);
  // It owns its camera and has no debug views: those keys stay idle.
  s.camera.fov_deg = 30.0f;
  s.scene_camera.fov_deg = 60.0f;
  press(s, GLFW_KEY_R);
  press(s, GLFW_KEY_C);
  press(s, GLFW_KEY_V);
  press(s, GLFW_KEY_3);
  EXPECT_EQ(s.camera.fov_deg, 30.0f);
  EXPECT_FALSE(s.want_write_camera);
  EXPECT_EQ(s.debug_view, 0);
  EXPECT_TRUE(press(s, GLFW_KEY_ESCAPE));
  // Its texture sees nothing: no channel reads it.
  for (std::uint8_t v : s.keys) ASSERT_EQ(v, 0);
}

TEST(LiveKeyBindings, TheLettersGoToTheShaderOnlyWhenItReadsTheKeyboard) {
  ViewState s = shader_state(false);
  press(s, GLFW_KEY_P);
  EXPECT_TRUE(s.want_shot);
  s.want_shot = false;
  s.shader_keys = true;  // a save added a keyboard channel
  press(s, GLFW_KEY_P);
  press(s, GLFW_KEY_P, GLFW_MOD_SHIFT);
  press(s, GLFW_KEY_SPACE);
  EXPECT_FALSE(s.want_shot);
  EXPECT_FALSE(s.want_window_shot);
  EXPECT_FALSE(s.paused);
  EXPECT_EQ(s.keys[80], 255);  // 'P' down, in Shadertoy's texture
  EXPECT_EQ(s.keys[32], 255);  // Space
  // The viewer keeps its F-keys and Escape.
  press(s, GLFW_KEY_F12);
  EXPECT_TRUE(s.want_shot);
  press(s, GLFW_KEY_F2);
  EXPECT_TRUE(s.paused);
  EXPECT_TRUE(press(s, GLFW_KEY_ESCAPE));
  // A scene keeps every binding, the camera's too.
  ViewState scene;
  scene.scene_camera.fov_deg = 60.0f;
  press(scene, GLFW_KEY_P);
  EXPECT_TRUE(scene.want_shot);
  press(scene, GLFW_KEY_R);
  EXPECT_EQ(scene.camera.fov_deg, 60.0f);
  press(scene, GLFW_KEY_3);
  EXPECT_EQ(scene.debug_view, 3);
  press(scene, GLFW_KEY_C);
  EXPECT_TRUE(scene.want_write_camera);
}

}  // namespace
}  // namespace ms::live
