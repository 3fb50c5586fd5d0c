// A scene's own uniforms, shown as sliders in the viewer's panel. A map file
// (or any file it includes, or a Shadertoy shader) opts a uniform in with a
// range in a comment on its declaration line:
//
//   uniform float uTwist = 0.5;                // range(0, 2)
//   uniform vec3  uTint  = vec3(1.0, 0.8, 0.6); // color
//   uniform int   uCount = 4;                  // range(1, 16)
//
// The initializer is GLSL's own, so `render` (which sets none of these) sees
// the same default. Types: float, int, vec2, vec3, vec4. No GL here.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace ms::live {

struct SceneParam {
  std::string name;
  std::string type;        // "float", "int", "vec2", "vec3", "vec4"
  int components = 1;
  bool is_int = false;
  bool color = false;      // `// color`: a vec3 colour picker, range [0, 1]
  float lo = 0.0f, hi = 1.0f;
  std::array<float, 4> initial{};  // the initializer (lo when there is none)
  std::array<float, 4> value{};    // what the panel set
};

// Every annotated uniform declaration in `glsl`, in order, each name once.
std::vector<SceneParam> parse_scene_params(std::string_view glsl);

// After a reload: a parameter whose type and initializer did not change keeps
// the value the user set; an edited initializer wins (the file changed).
void carry_over_values(std::vector<SceneParam>& fresh, const std::vector<SceneParam>& old);

}  // namespace ms::live
