// A scene's own uniforms: those a map file (or any file it includes, or a
// Shadertoy shader) opts in with a range in a comment on its declaration
// line. The viewer shows them as sliders (live/panel.h); `--uniform
// NAME=VALUE` sets their value for a render, `view` included:
//
//   uniform float uTwist = 0.5;                // range(0, 2)
//   uniform vec3  uTint  = vec3(1.0, 0.8, 0.6); // color
//   uniform int   uCount = 4;                  // range(1, 16)
//
//   std::vector<SceneParam> params = parse_scene_params(src.text);
//   set_uniform_defaults(src.text, {{"uTwist", {1.25}}});  // throws for a bad value
//
// The initializer is GLSL's own, so `render` (which sets none of these) sees
// the same default as the viewer. A value given with --uniform becomes that
// initializer: every consumer of the assembled text (render, the viewer's
// panel, --print-shader, fingerprints) sees it. Types: float, int, vec2,
// vec3, vec4. No GL here.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace ms {

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

// One --uniform NAME=VALUE: the value's numbers, one per component.
struct UniformValue {
  std::string name;
  std::vector<double> values;
};

// Makes each value the initializer of its ranged uniform's declaration in
// `glsl` (the first declaration of that name, as parse_scene_params()).
// Returns, for each of `values` in order, whether `glsl` declares it; a
// value of the wrong type, component count or out of the declared range is
// an ms::Error (bad input) naming "--uniform NAME".
std::vector<bool> set_uniform_defaults(std::string& glsl, const std::vector<UniformValue>& values);

// Throws bad input for the first value not `found` in any pass, with a
// did-you-mean over `declared` (every ranged uniform of every pass).
void check_uniforms_found(const std::vector<UniformValue>& values, const std::vector<bool>& found,
                          const std::vector<SceneParam>& declared);

}  // namespace ms
