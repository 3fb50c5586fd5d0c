// GL contexts behind one small interface. A Context owns a current GL 4.5
// core context and the loaded entry points until it is destroyed.
#pragma once
#include <memory>
#include <string>

struct GLFWwindow;

namespace ms {

enum class Backend { automatic, egl, osmesa };

// "auto" | "egl" | "osmesa"; throws a bad_input Error otherwise.
Backend parse_backend(const std::string& name);
const char* backend_name(Backend b);

struct GlInfo {
  std::string vendor;
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;
  int max_viewport[2] = {0, 0};
  int max_texture_size = 0;
  int max_renderbuffer_size = 0;
  // Mesa's CPU rasterizers (llvmpipe, softpipe): shaders run on this
  // process's threads, so its CPU time is the frame's work; their GL timer
  // queries do not cover the last flush of a frame.
  bool software() const {
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
  }
};

class Context {
 public:
  virtual ~Context() = default;
  Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Which backend this context came from ("egl-device", "egl-surfaceless", "osmesa").
  virtual std::string backend() const = 0;
  const GlInfo& info() const { return info_; }

 protected:
  void load_info();  // fills info_ once GL entry points are loaded
  GlInfo info_;
};

// Headless context. automatic tries EGL (GPU device first, then Mesa's
// surfaceless platform), then OSMesa. Throws Exit::system when none works,
// with every attempt's reason in the message.
std::unique_ptr<Context> create_headless_context(Backend backend);

// WebGL starts every local variable at zero and desktop GL does not, so a
// Shadertoy shader that reads one before writing it renders differently.
// Mesa's driconf option glsl_zero_init does what WebGL does; this turns it
// on for contexts made from now on (unless the environment already says
// otherwise). Mesa's EGL and GLFW contexts honour it; OSMesa reads no
// driconf, other drivers have no such option (docs/shadertoy.md).
void request_zero_initialised_locals();

// Backend-specific constructors; each throws Exit::system on failure.
std::unique_ptr<Context> create_egl_context();
std::unique_ptr<Context> create_osmesa_context();

// A visible window with a GL 4.5 core context (GLFW; the viewer), current on
// this thread. `window` receives the GLFWwindow, which lives as long as the
// Context. Throws Exit::system when there is no display. In marchlive.
std::unique_ptr<Context> create_window_context(int width, int height, const std::string& title,
                                               GLFWwindow*& window);

// A hidden 1x1 window whose GL context shares objects (programs, textures;
// not framebuffers or vertex arrays) with `share`'s, for the viewer's compile
// worker (live/compile_worker.h) to make current on its own thread. Call it
// on the thread that made `share`, after create_window_context (its hints
// still hold). Null when the driver refuses one; glfwDestroyWindow it before
// the Context goes. In marchlive.
GLFWwindow* create_shared_hidden_window(GLFWwindow* share);

}  // namespace ms
