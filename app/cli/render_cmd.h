// `marchstudio render`: a scene (.toml) or a Shadertoy shader (.glsl) to an
// image file, headless.
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ms {

struct RenderArgs {
  std::string input;
  std::string output;     // empty: <input stem>.png in the current directory
  std::string size;       // "WxH", empty: the scene's
  double time = 0.0;      // seconds; explicit default 0, never the wall clock
  bool time_set = false;
  int spp = 0;            // 0: the scene's
  int frame = 0;
  std::string backend = "auto";
  std::string shader_dir; // empty: MARCH_SHADER_DIR or the built-in location
  std::vector<std::string> disable;  // effects switched off: shadows, reflections, ao, checker-filter
  std::vector<std::string> defines;  // -D NAME[=VALUE], injected into the scene shader
  bool verbose = false;
};

CLI::App* add_render_command(CLI::App& app, RenderArgs& args);
int run_render(const RenderArgs& args);

}  // namespace ms
