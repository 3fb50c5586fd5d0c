// Where sdf_shaders/ lives: --shader-dir, then $MARCH_SHADER_DIR, then next to
// an installed binary (../share/marchstudio/sdf_shaders), then the source tree.
#pragma once
#include <filesystem>
#include <string>

namespace ms {

// Throws bad_input when the chosen directory has no main.frag.
std::filesystem::path resolve_shader_dir(const std::string& flag_value);

}  // namespace ms
