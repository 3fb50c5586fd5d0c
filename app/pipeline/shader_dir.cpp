#include "pipeline/shader_dir.h"

#include <unistd.h>

#include <cstdlib>
#include <vector>

#include "core/error.h"

namespace ms {
namespace fs = std::filesystem;

static fs::path exe_dir() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : p.parent_path();
}

fs::path resolve_shader_dir(const std::string& flag_value) {
  std::error_code ec;
  if (!flag_value.empty()) {
    if (!fs::is_regular_file(fs::path(flag_value) / "main.frag", ec))
      fail_input("no main.frag in the shader directory", flag_value, 0, "--shader-dir");
    return fs::absolute(flag_value);
  }
  if (const char* env = std::getenv("MARCH_SHADER_DIR"); env && *env) {
    if (!fs::is_regular_file(fs::path(env) / "main.frag", ec))
      fail_input("no main.frag in $MARCH_SHADER_DIR", env, 0, "MARCH_SHADER_DIR");
    return fs::absolute(env);
  }
  std::vector<fs::path> candidates;
  if (fs::path d = exe_dir(); !d.empty()) candidates.push_back(d / "../share/marchstudio/sdf_shaders");
  candidates.push_back(MARCH_SOURCE_SHADER_DIR);
  for (const fs::path& c : candidates)
    if (fs::is_regular_file(c / "main.frag", ec)) return fs::weakly_canonical(c);
  fail_system("cannot find sdf_shaders/ (set --shader-dir or MARCH_SHADER_DIR)");
}

}  // namespace ms
