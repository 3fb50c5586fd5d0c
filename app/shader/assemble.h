// Builds the root GLSL for a scene (or the post pass) per the host <-> GLSL
// contract (#defines from the Scene, then the sdf_shaders/ includes) and runs
// it through preprocess(). No GL here.
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"
#include "shader/preprocess.h"

namespace ms {

struct AssembleOptions {
  std::filesystem::path shader_dir;  // the sdf_shaders/ directory
  // Extra #defines (name, value) placed after the scene's own, e.g.
  // AOV_OUTPUTS or DEBUG_VIEW; a name the scene already defines is an error.
  std::vector<std::pair<std::string, std::string>> defines;
};

// The scene's main-pass fragment shader: NUM_LIGHTS, NUM_MATERIALS,
// MAT_<NAME> per material (ids in TOML order), the quality defines, then
// prelude/primitives/operators, the scene's map file (absolute) and main.frag.
// Source string 0 is shown as "<scene name>.frag (generated)".
ShaderSource assemble_scene(const Scene& scene, const AssembleOptions& opts);

// The post pass: TONEMAP (0 none, 1 Reinhard, 2 ACES) and ENCODE_SRGB, then
// post.frag.
ShaderSource assemble_post(Tonemap tonemap, bool encode_srgb, const AssembleOptions& opts);

// The shared vertex shader: one triangle covering the viewport, positions
// from gl_VertexID, no attributes (the host still binds an empty VAO).
std::string fullscreen_vertex_source();

// A float as a GLSL float literal that parses back to exactly `v`: the
// shortest round-trip digits, always with a '.' or an exponent ("100.0",
// "0.5", "1e-04"), negatives parenthesised. Throws ms::Error for inf/NaN.
std::string glsl_float(float v);

}  // namespace ms
