// The lean GPU bench has no OSMesa: EGL (device platform) is the point.
#include "core/error.h"
#include "gl/context.h"

namespace ms {
std::unique_ptr<Context> create_osmesa_context() { fail_system("OSMesa is not built into marchstudio-gpubench"); }
}  // namespace ms
