#include "gl/context.h"

#include <cstdlib>

#include "core/error.h"
#include "gl/gl.h"

namespace ms {

Backend parse_backend(const std::string& name) {
  if (name == "auto") return Backend::automatic;
  if (name == "egl") return Backend::egl;
  if (name == "osmesa") return Backend::osmesa;
  fail_input("unknown backend '" + name + "'", {}, 0, "--backend", "expected auto, egl or osmesa");
}

const char* backend_name(Backend b) {
  switch (b) {
    case Backend::automatic: return "auto";
    case Backend::egl: return "egl";
    case Backend::osmesa: return "osmesa";
  }
  return "?";
}

static std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

void Context::load_info() {
  info_.vendor = gl_string(GL_VENDOR);
  info_.renderer = gl_string(GL_RENDERER);
  info_.version = gl_string(GL_VERSION);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, info_.max_viewport);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info_.max_texture_size);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &info_.max_renderbuffer_size);
}

std::unique_ptr<Context> create_headless_context(Backend backend) {
  if (backend == Backend::egl) return create_egl_context();
  if (backend == Backend::osmesa) return create_osmesa_context();
  std::string why;
  try {
    return create_egl_context();
  } catch (const Error& e) {
    why = e.info().what;
  }
  try {
    return create_osmesa_context();
  } catch (const Error& e) {
    fail_system("no GL context: EGL: " + why + "; OSMesa: " + e.info().what);
  }
}

void request_zero_initialised_locals() {
  ::setenv("glsl_zero_init", "true", 0);
  // Mesa announces every driconf value set from the environment on stderr
  // ("ATTENTION: ... overridden by environment") unless told to be silent.
  ::setenv("MESA_DEBUG", "silent", 0);
}

}  // namespace ms
