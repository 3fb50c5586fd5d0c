// live/keyboard.h: Shadertoy's keyboard texture, by JavaScript key code:
// row 0 down, row 1 pressed this frame, row 2 toggled by each press.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "live/keyboard.h"

namespace ms::live {
namespace {

TEST(LiveKeyboard, KeyCodesAreJavaScripts) {
  EXPECT_EQ(js_key_code(GLFW_KEY_A), 65);
  EXPECT_EQ(js_key_code(GLFW_KEY_7), 55);
  EXPECT_EQ(js_key_code(GLFW_KEY_SPACE), 32);
  EXPECT_EQ(js_key_code(GLFW_KEY_LEFT), 37);
  EXPECT_EQ(js_key_code(GLFW_KEY_UP), 38);
  EXPECT_EQ(js_key_code(GLFW_KEY_RIGHT), 39);
  EXPECT_EQ(js_key_code(GLFW_KEY_DOWN), 40);
  EXPECT_EQ(js_key_code(GLFW_KEY_LEFT_SHIFT), 16);
  EXPECT_EQ(js_key_code(GLFW_KEY_F1), 112);
  EXPECT_EQ(js_key_code(GLFW_KEY_SEMICOLON), 186);
  EXPECT_EQ(js_key_code(GLFW_KEY_KP_3), 99);
  EXPECT_EQ(js_key_code(GLFW_KEY_UNKNOWN), -1);
}

TEST(LiveKeyboard, DownPressedAndToggledRows) {
  KeyboardState k{};
  keyboard_event(k, GLFW_KEY_W, GLFW_PRESS);
  EXPECT_EQ(k[87], 255);        // down
  EXPECT_EQ(k[256 + 87], 255);  // pressed this frame
  EXPECT_EQ(k[512 + 87], 255);  // toggled on
  keyboard_frame_done(k);
  EXPECT_EQ(k[87], 255);
  EXPECT_EQ(k[256 + 87], 0);    // only for the frame it was pressed
  keyboard_event(k, GLFW_KEY_W, GLFW_REPEAT);
  EXPECT_EQ(k[256 + 87], 0);    // a repeat is no new press
  keyboard_event(k, GLFW_KEY_W, GLFW_RELEASE);
  EXPECT_EQ(k[87], 0);
  EXPECT_EQ(k[512 + 87], 255);  // a toggle outlives the release
  keyboard_event(k, GLFW_KEY_W, GLFW_PRESS);
  EXPECT_EQ(k[512 + 87], 0);    // toggled off by the second press
}

}  // namespace
}  // namespace ms::live
