// The Shadertoy wrapper: looks_like_shadertoy() on any text, then the text
// as scene/shader.glsl through assemble_shadertoy() with the real
// sdf_shaders/ as the library. Only ms::Error may escape, and no output or
// error holds the canary (scene/escape.glsl and scene/up/ lead outside).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "fuzz_util.h"
#include "importers/shadertoy.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ms;
  fuzz::Workspace& ws = fuzz::workspace();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The canary must come from the secret file, not from the input itself.
  if (fuzz::leaks_canary(text)) return 0;
  const bool looks = looks_like_shadertoy(text);
  const auto file = ws.scene() / "shader.glsl";
  fuzz::put(file, text);
  AssembleOptions opts;
  opts.shader_dir = MARCH_SOURCE_SHADER_DIR;
  if (size > 0 && data[0] == 'D') opts.defines.emplace_back("FUZZ_DEFINE", "1");
  try {
    const ShaderSource src = assemble_shadertoy(file, opts);
    if (fuzz::leaks_canary(src.text)) fuzz::violated("wrapped shader holds the canary", src.text);
    (void)looks;
  } catch (const Error& e) {
    if (fuzz::leaks_canary(e.what())) fuzz::violated("shadertoy error shows the canary", e.what());
  }
  return 0;
}
