// The scene file's schema (docs/scene-format.md): the typed fields of each
// table and every table's accepted keys, for unknown-key errors and for
// hints naming where a misplaced key belongs. scene/load.cpp reads with it.
//
//   const Schema schema;
//   schema.check(reader, table, "camera", "camera");  // throws at the bad key's line
#pragma once
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "scene/load_geometry.h"
#include "scene/quality_fields.h"
#include "scene/scene.h"
#include "core/suggest.h"
#include "scene/toml_read.h"

namespace ms {

inline constexpr Range kNonNeg = Range::at_least(0);
inline constexpr Range kPositive = Range::above(0);

// The schema (docs/scene-format.md), one line per key. Keys that need more
// than a typed read (strings, enums) are listed as extras where checked.
inline const Field<Camera> kCameraFields[] = {
    {"position", &Camera::position},
    {"target", &Camera::target},
    {"up", &Camera::up},
    {"fov", &Camera::fov_deg, Range::open(0, 180)},
};
inline const Field<RenderSettings> kRenderFields[] = {
    {"width", &RenderSettings::width, Range::closed(1, 16384)},
    {"height", &RenderSettings::height, Range::closed(1, 16384)},
    {"spp", &RenderSettings::spp, Range::closed(1, 1024)},
    {"time", &RenderSettings::time},
    {"exposure", &RenderSettings::exposure, kPositive},
};
inline const Field<Sky> kSkyFields[] = {
    {"horizon", &Sky::horizon, kNonNeg},
    {"zenith", &Sky::zenith, kNonNeg},
    {"ambient", &Sky::ambient, kNonNeg},
    {"rotation", &Sky::rotation, Range::closed(-360.0, 360.0)},
    {"intensity", &Sky::intensity, kNonNeg},
};
inline const Field<Light> kLightFields[] = {
    {"position", &Light::position},
    {"direction", &Light::direction},
    {"color", &Light::color, kNonNeg},
    {"intensity", &Light::intensity, kNonNeg},
    {"size", &Light::size, kNonNeg},
    {"attenuation", &Light::attenuation, kNonNeg},
};
inline const Field<Material> kMaterialFields[] = {
    {"color", &Material::color, kNonNeg},
    {"ambient", &Material::ambient, kNonNeg},
    {"diffuse", &Material::diffuse, kNonNeg},
    {"specular", &Material::specular, kNonNeg},
    {"shininess", &Material::shininess, kPositive},
    {"reflectivity", &Material::reflectivity, Range::closed(0, 1)},
    {"color2", &Material::color2, kNonNeg},
    {"pattern_scale", &Material::pattern_scale, kPositive},
    {"pattern_velocity", &Material::pattern_velocity},
};

// Every table's accepted keys, for unknown-key checks and for hinting where
// a misplaced key belongs ("'width' belongs in [render]").
struct Section {
  std::string_view name;
  bool array;  // [[name]] rather than [name]
  std::vector<std::string_view> keys;
};

struct Schema {
  std::vector<std::string_view> top{"scene",  "camera", "render", "sky",       "quality",   "lights",
                                    "materials", "planes", "bounds", "animation", "shadertoy", "passes", "post"};
  std::vector<Section> sections{
      {"scene", false, {"name", "map", "shadertoy", "graph"}},
      {"camera", false, keys_of(kCameraFields)},
      {"render", false, keys_of(kRenderFields, {"tonemap"})},
      {"sky", false, keys_of(kSkyFields, {"environment"})},
      {"quality", false, keys_of(kQualityFields, {"preset"})},
      {"lights", true, keys_of(kLightFields, {"type"})},
      {"materials", true, keys_of(kMaterialFields, {"name", "pattern"})},
      {"planes", true, keys_of(kPlaneFields, {"material"})},
      {"bounds", false, keys_of(kBoundsFields)},
      {"animation", true, {"target", "interpolation", "keys"}},  // scene/animation.cpp
  };

  const Section& section(std::string_view name) const {
    return *std::find_if(sections.begin(), sections.end(), [&](const Section& s) { return s.name == name; });
  }
  // Hint for a key unknown in `here` but valid in another table.
  std::string elsewhere(std::string_view here, std::string_view key) const {
    for (const Section& s : sections) {
      if (s.name == here || std::find(s.keys.begin(), s.keys.end(), key) == s.keys.end()) continue;
      std::string hint = quote(key);
      hint.append(" belongs in ").append(s.array ? "[[" : "[").append(s.name).append(s.array ? "]]" : "]");
      return hint;
    }
    return {};
  }
  void check(const Reader& r, const toml::table& t, std::string_view section_name, std::string_view path) const {
    r.check_keys(t, path, section(section_name).keys, [&](std::string_view key) -> std::string {
      // A [render] size is the image's, not a light's (which the generic hint would name).
      if (section_name == "render" && (key == "size" || key == "resolution"))
        return "the image size is width and height, or --size WxH on the command line";
      return elsewhere(section_name, key);
    });
  }
};

}  // namespace ms
