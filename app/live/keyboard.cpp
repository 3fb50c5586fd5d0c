#include "live/keyboard.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ms::live {

int js_key_code(int k) {
  if ((k >= GLFW_KEY_A && k <= GLFW_KEY_Z) || (k >= GLFW_KEY_0 && k <= GLFW_KEY_9) || k == GLFW_KEY_SPACE) return k;
  if (k >= GLFW_KEY_F1 && k <= GLFW_KEY_F12) return 112 + (k - GLFW_KEY_F1);
  if (k >= GLFW_KEY_KP_0 && k <= GLFW_KEY_KP_9) return 96 + (k - GLFW_KEY_KP_0);
  switch (k) {
    case GLFW_KEY_ESCAPE: return 27;
    case GLFW_KEY_ENTER: return 13;
    case GLFW_KEY_TAB: return 9;
    case GLFW_KEY_BACKSPACE: return 8;
    case GLFW_KEY_INSERT: return 45;
    case GLFW_KEY_DELETE: return 46;
    case GLFW_KEY_RIGHT: return 39;
    case GLFW_KEY_LEFT: return 37;
    case GLFW_KEY_DOWN: return 40;
    case GLFW_KEY_UP: return 38;
    case GLFW_KEY_PAGE_UP: return 33;
    case GLFW_KEY_PAGE_DOWN: return 34;
    case GLFW_KEY_HOME: return 36;
    case GLFW_KEY_END: return 35;
    case GLFW_KEY_LEFT_SHIFT:
    case GLFW_KEY_RIGHT_SHIFT: return 16;
    case GLFW_KEY_LEFT_CONTROL:
    case GLFW_KEY_RIGHT_CONTROL: return 17;
    case GLFW_KEY_LEFT_ALT:
    case GLFW_KEY_RIGHT_ALT: return 18;
    case GLFW_KEY_SEMICOLON: return 186;
    case GLFW_KEY_EQUAL: return 187;
    case GLFW_KEY_COMMA: return 188;
    case GLFW_KEY_MINUS: return 189;
    case GLFW_KEY_PERIOD: return 190;
    case GLFW_KEY_SLASH: return 191;
    case GLFW_KEY_GRAVE_ACCENT: return 192;
    case GLFW_KEY_LEFT_BRACKET: return 219;
    case GLFW_KEY_BACKSLASH: return 220;
    case GLFW_KEY_RIGHT_BRACKET: return 221;
    case GLFW_KEY_APOSTROPHE: return 222;
    default: return -1;
  }
}

void keyboard_event(KeyboardState& keys, int glfw_key, int action) {
  const int code = js_key_code(glfw_key);
  if (code < 0 || code > 255 || action == GLFW_REPEAT) return;
  if (action == GLFW_PRESS) {
    keys[code] = 255;
    keys[256 + code] = 255;
    keys[512 + code] = keys[512 + code] ? 0 : 255;
  } else if (action == GLFW_RELEASE) {
    keys[code] = 0;
  }
}

void keyboard_frame_done(KeyboardState& keys) {
  for (int i = 256; i < 512; ++i) keys[i] = 0;
}

}  // namespace ms::live
