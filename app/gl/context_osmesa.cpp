// OSMesa: the pure-software fallback. It needs a client-memory colour buffer
// to be made current; we render into FBOs, so a tiny one is enough.
#include "gl/gl.h"  // before osmesa.h: glad's header guards out GL/gl.h

#include <GL/osmesa.h>

#include <vector>

#include "core/error.h"
#include "gl/context.h"

namespace ms {
namespace {

constexpr int kBufferSize = 16;

class OsmesaContext final : public Context {
 public:
  explicit OsmesaContext(OSMesaContext ctx) : ctx_(ctx), buffer_(kBufferSize * kBufferSize * 4) {
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize, kBufferSize)) {
      OSMesaDestroyContext(ctx_);
      fail_system("OSMesa: cannot make the context current");
    }
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
      OSMesaDestroyContext(ctx_);
      fail_system("OSMesa: cannot load GL entry points");
    }
    load_info();
  }
  ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }
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
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) fail_system("OSMesa: cannot create a GL 4.5 core context");
  return std::make_unique<OsmesaContext>(ctx);
}

}  // namespace ms
