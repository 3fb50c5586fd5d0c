// The lean GPU bench reads no images: no OpenImageIO module beside it, and
// a Shadertoy texture input is refused in one line.
#include "core/error.h"
#include "io/image_io.h"

namespace ms {
Image read_image(const std::filesystem::path& path, AlphaMode) {
  fail_system("images (textures) are not built into marchstudio-gpubench", path.string());
}
}  // namespace ms
