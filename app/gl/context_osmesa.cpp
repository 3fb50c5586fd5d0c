// OSMesa: the pure-software fallback. It needs a client-memory colour buffer
// to be made current; we render into FBOs, so a tiny one is enough.
// libOSMesa is opened with dlopen when this backend is chosen, not linked:
// it pulls in LLVM, about 20 ms of dynamic loading that --version, --help
// and every EGL run would otherwise pay (docs/performance.md#start-up).
#include "gl/gl.h"  // before osmesa.h: glad's header guards out GL/gl.h

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "gl/context.h"

namespace ms {
namespace {

constexpr int kBufferSize = 16;

// The four entry points we use, from the library opened on first use.
struct OsmesaApi {
  decltype(&OSMesaCreateContextAttribs) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;
};

const OsmesaApi& osmesa() {
  static const OsmesaApi api = [] {
    OsmesaApi a;
    void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!lib) fail_system(std::string("OSMesa: cannot load libOSMesa.so.8: ") + dlerror());
    a.create = reinterpret_cast<decltype(a.create)>(dlsym(lib, "OSMesaCreateContextAttribs"));
    a.make_current = reinterpret_cast<decltype(a.make_current)>(dlsym(lib, "OSMesaMakeCurrent"));
    a.get_proc = reinterpret_cast<decltype(a.get_proc)>(dlsym(lib, "OSMesaGetProcAddress"));
    a.destroy = reinterpret_cast<decltype(a.destroy)>(dlsym(lib, "OSMesaDestroyContext"));
    if (!a.create || !a.make_current || !a.get_proc || !a.destroy)
      fail_system("OSMesa: libOSMesa.so.8 lacks the GL 4.5 core context entry points");
    return a;
  }();
  return api;
}

class OsmesaContext final : public Context {
 public:
  explicit OsmesaContext(OSMesaContext ctx) : ctx_(ctx), buffer_(kBufferSize * kBufferSize * 4) {
    if (!osmesa().make_current(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize, kBufferSize)) {
      osmesa().destroy(ctx_);
      fail_system("OSMesa: cannot make the context current");
    }
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(osmesa().get_proc))) {
      osmesa().destroy(ctx_);
      fail_system("OSMesa: cannot load GL entry points");
    }
    load_info();
  }
  ~OsmesaContext() override { osmesa().destroy(ctx_); }
  std::string backend() const override { return "osmesa"; }

 private:
  OSMesaContext ctx_;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<Context> create_osmesa_context() {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                         OSMESA_DEPTH_BITS, 0,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 4,
                         OSMESA_CONTEXT_MINOR_VERSION, 5,
                         0};
  OSMesaContext ctx = osmesa().create(attribs, nullptr);
  if (!ctx) fail_system("OSMesa: cannot create a GL 4.5 core context");
  return std::make_unique<OsmesaContext>(ctx);
}

}  // namespace ms
