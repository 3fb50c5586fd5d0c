// GLFW window context for the viewer: a visible window with a GL 4.5 core
// context, entry points loaded through glfwGetProcAddress (GLX or EGL, as
// GLFW chooses). Built into marchlive, so headless tools never link GLFW.
#include "gl/gl.h"  // glad first: GLFW must not pull in a system GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "gl/context.h"

namespace ms {
namespace {

// GLFW keeps the last error per thread; no callback (and no global) needed.
std::string glfw_error() {
  const char* desc = nullptr;
  const int code = glfwGetError(&desc);
  if (code == GLFW_NO_ERROR) return "unknown GLFW error";
  return desc ? desc : "GLFW error " + std::to_string(code);
}

class GlfwContext final : public Context {
 public:
  explicit GlfwContext(GLFWwindow* window) : window_(window) { load_info(); }
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  std::string backend() const override { return "glfw"; }

 private:
  GLFWwindow* window_;
};

}  // namespace

std::unique_ptr<Context> create_window_context(int width, int height, const std::string& title,
                                               GLFWwindow*& window) {
  if (!glfwInit()) fail_system("no window: " + glfw_error() + " (is DISPLAY set? try xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // The window shows a display-encoded image already; no second sRGB encode.
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window) {
    const std::string why = glfw_error();
    glfwTerminate();
    fail_system("cannot open a GL 4.5 core window: " + why);
  }
  glfwMakeContextCurrent(window);
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
    glfwDestroyWindow(window);
    glfwTerminate();
    window = nullptr;
    fail_system("GLFW: cannot load GL entry points");
  }
  glfwSwapInterval(1);
  return std::make_unique<GlfwContext>(window);
}

GLFWwindow* create_shared_hidden_window(GLFWwindow* share) {
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* w = glfwCreateWindow(1, 1, "marchstudio compile", nullptr, share);
  glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
  return w;
}

}  // namespace ms
