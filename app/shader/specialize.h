// Per-scene shader specialization (docs/specialization.md): from a Scene and
// its FeatureSet, the #defines and generated GLSL that leave only the code
// the scene uses in the assembled shader, with the values nobody can change
// at run time folded into constants. assemble_scene() calls this; no GL here.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/features.h"
#include "scene/scene.h"

namespace ms {

enum class Specialization {
  // --no-specialize: every feature the quality settings allow is compiled,
  // lights in a loop that branches on their kind, materials, lights and sky
  // read from uniforms. What the library compiles when nothing is defined.
  generic,
  // Only the features the scene uses, lights unrolled; every value the
  // viewer's panel can drag (lights, materials, sky) stays a uniform (what
  // `view` compiled before it folded; kept for comparisons).
  uniforms,
  // `render`, `bench`, `view`: only the features the scene uses, and lights,
  // materials and sky folded into constants, except the tables an
  // [[animation]] track drives or a live value (a panel drag) is in, which
  // stay uniforms.
  folded,
};

const char* specialization_name(Specialization s);  // "generic", "uniforms", "folded"

// What uLights[i] holds for a light, and what a folded light is compiled
// with: render/uniforms.cpp uploads exactly these values, so a folded and a
// uniform light compute the same thing.
struct GlslLight {
  glm::vec4 pos{0.0f};    // point: (position, 1); directional: (unit travel direction, 0)
  glm::vec3 color{0.0f};  // colour * intensity
  float size = 0.0f;      // point: radius; directional: angular radius in radians
  glm::vec3 atten{1.0f, 0.0f, 0.0f};
};
GlslLight glsl_light(const Light& l);

struct Specialized {
  Quality quality;        // the scene's, with the features it does not use switched off
  std::string defines;    // "#define ..." lines for the root, after the scene's own
  std::string constants;  // GLSL for the root right after prelude.glsl: folded values
};

// Nothing (and the scene's quality) for Specialization::generic. Otherwise:
// SPECIALIZED 1; ENABLE_SHADOWS/AO/REFLECTIONS and MAX_BOUNCES from the
// features; USE_CHECKER and MATERIAL_IS_CHECKER(id); NUM_POINT_LIGHTS,
// NUM_DIRECTIONAL_LIGHTS and LIGHT_IS_POINT(i); LIGHT_/MATERIAL_/SKY_UNIFORMS
// with, for what is folded, constant tables (kLight*, sceneMaterial(), the
// sky's names as constants); MS_LIBRARY_SUBSET with USE_<NAME> for every
// name in f.library. The rule for what stays a uniform: docs/specialization.md.
// `live` names values the viewer's panel is dragging, as folded_differences()
// names them: each such value ("materials[2].color", "lights[0].position",
// "sky.horizon") is read from its own uniform, live_uniform_name(), the
// rest of its table stays folded. A whole entry ("materials[2]") keeps its
// table uniforms, as an animated table does.
Specialized specialize(const Scene& scene, const FeatureSet& f, Specialization mode,
                       const std::vector<std::string>& live = {});

// The folded values that differ between a and b, in table order: what a
// program folded from `a` shows wrong for `b`. One name per value as the
// shader holds it: "materials[1].shininess" (the file's key), a light by
// GLSL slot ("lights[0].position" or ".direction", ".color" for colour and
// intensity, ".size", ".attenuation"), "sky.zenith"; a whole entry
// ("lights[1]") when the tables' lengths or a light's kind differ.
std::vector<std::string> folded_differences(const Scene& a, const Scene& b);

// Light i's live name for GLSL slot "pos", "color", "size" or "atten".
std::string live_light_name(const Light& light, size_t i, const std::string& slot);
// The uniform a live value is read from: "materials[1].color" ->
// uLive_materials_1_color, "lights[0].position" -> uLive_lights_0_pos (by
// slot: _pos, _color, _size, _atten), "sky.horizon" -> uSkyHorizon.
std::string live_uniform_name(const std::string& name);

// The program cache's key: 64-bit FNV-1a over the vertex source, then the
// fragment source. Equal sources give equal keys in every process.
std::uint64_t program_key(std::string_view vertex_source, std::string_view fragment_source);

}  // namespace ms
