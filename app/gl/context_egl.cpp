// EGL headless context: a GPU through the EGL device platform when one is
// there (NVIDIA, DRM devices), otherwise Mesa's surfaceless platform
// (llvmpipe). Surfaceless: we render only into FBOs.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

#include "core/error.h"
#include "gl/context.h"
#include "gl/gl.h"

namespace ms {
namespace {

template <class Fn>
Fn egl_proc(const char* name) {
  return reinterpret_cast<Fn>(eglGetProcAddress(name));
}

bool has_extension(const char* list, const char* ext) {
  if (!list) return false;
  const std::string s = std::string(" ") + list + " ";
  return s.find(std::string(" ") + ext + " ") != std::string::npos;
}

// The first hardware device (not Mesa's software device), or none.
EGLDisplay open_device_display() {
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client_ext, "EGL_EXT_device_enumeration") &&
      !has_extension(client_ext, "EGL_EXT_device_base"))
    return EGL_NO_DISPLAY;
  auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_device_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  auto get_platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!query_devices || !get_platform_display) return EGL_NO_DISPLAY;
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
  std::vector<EGLDeviceEXT> devices(count);
  query_devices(count, devices.data(), &count);
  for (EGLDeviceEXT dev : devices) {
    const char* ext = query_device_string ? query_device_string(dev, EGL_EXTENSIONS) : nullptr;
    if (has_extension(ext, "EGL_MESA_device_software")) continue;
    EGLDisplay dpy = get_platform_display(EGL_PLATFORM_DEVICE_EXT, dev, nullptr);
    if (dpy == EGL_NO_DISPLAY) continue;
    EGLint major = 0, minor = 0;
    if (eglInitialize(dpy, &major, &minor)) return dpy;
  }
  return EGL_NO_DISPLAY;
}

EGLDisplay open_surfaceless_display() {
  auto get_platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!get_platform_display) return EGL_NO_DISPLAY;
  EGLDisplay dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) return EGL_NO_DISPLAY;
  return dpy;
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay dpy, EGLContext ctx, std::string kind) : dpy_(dpy), ctx_(ctx), kind_(std::move(kind)) {
    load_info();
  }
  ~EglContext() override {
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy_, ctx_);
    eglTerminate(dpy_);
  }
  std::string backend() const override { return kind_; }

 private:
  EGLDisplay dpy_;
  EGLContext ctx_;
  std::string kind_;
};

}  // namespace

std::unique_ptr<Context> create_egl_context() {
  std::string kind = "egl-device";
  EGLDisplay dpy = open_device_display();
  if (dpy == EGL_NO_DISPLAY) {
    kind = "egl-surfaceless";
    dpy = open_surfaceless_display();
  }
  if (dpy == EGL_NO_DISPLAY) fail_system("EGL: no device or surfaceless display");
  if (!has_extension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    eglTerminate(dpy);
    fail_system("EGL: display lacks EGL_KHR_surfaceless_context");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(dpy);
    fail_system("EGL: cannot bind the OpenGL API");
  }
  // eglChooseConfig defaults to window surfaces, which surfaceless displays lack.
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, config_attribs, &config, 1, &n) || n < 1) {
    eglTerminate(dpy);
    fail_system("EGL: no OpenGL-capable config");
  }
  const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT) {
    eglTerminate(dpy);
    fail_system("EGL: cannot create a GL 4.5 core context");
  }
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    fail_system("EGL: cannot make the context current");
  }
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) {
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    fail_system("EGL: cannot load GL entry points");
  }
  return std::make_unique<EglContext>(dpy, ctx, kind);
}

}  // namespace ms
