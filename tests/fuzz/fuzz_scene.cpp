// The TOML scene loader: any text either loads or fails with one ms::Error,
// never a crash, a hang or another exception. A scene that loads also poses
// (animated) and assembles, and whatever it names (scene.map through "..",
// a symlink or an absolute path) never brings the canary file into the
// shader or an error message.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "fuzz_util.h"
#include "scene/animation.h"
#include "scene/load.h"
#include "shader/assemble.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ms;
  fuzz::Workspace& ws = fuzz::workspace();
  static const bool ready = [&] {
    fuzz::put(ws.scene() / "map.glsl", "vec2 map(vec3 p) { return vec2(length(p) - 1.0, 0.0); }\n");
    fuzz::put(ws.scene() / "st.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
    return true;
  }();
  (void)ready;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The canary must come from the secret file, not from the input itself.
  if (fuzz::leaks_canary(text)) return 0;
  Scene scene;
  try {
    scene = parse_scene(text, ws.scene() / "fuzz.toml");
  } catch (const Error& e) {
    if (fuzz::leaks_canary(e.what())) fuzz::violated("scene error shows the canary", e.what());
    return 0;
  }
  try {
    for (double t : {-1.0, 0.0, 0.37, 2.0, 1e6}) animated(scene, t);
  } catch (const Error&) {
  }
  if (!scene.map_file.empty()) {
    try {
      AssembleOptions opts;
      opts.shader_dir = MARCH_SOURCE_SHADER_DIR;
      const ShaderSource src = assemble_scene(scene, opts);
      if (fuzz::leaks_canary(src.text)) fuzz::violated("assembled scene holds the canary", scene.map_file.string());
    } catch (const Error& e) {
      if (fuzz::leaks_canary(e.what())) fuzz::violated("assembly error shows the canary", e.what());
    }
  }
  return 0;
}
