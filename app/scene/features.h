// FeatureSet: what a scene actually uses, derived from the Scene and the
// GLSL of its map. shader/specialize.h turns it into compile-time defines so
// the assembled shader holds only that code (docs/specialization.md).
// No GL and no file access here: the caller passes the map's text.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace ms {

struct FeatureSet {
  std::vector<LightKind> lights;  // the kind of every light, in file order
  bool reflective = false;        // a material can reflect (reflectivity > 0, now or in a keyframe)
                                  // and reflections are on with at least one bounce
  int max_bounces = 0;            // quality.bounces when reflective, else 0
  bool shadows = false;           // quality.shadows, shadow_steps > 0 and at least one light
  bool ao = false;                // quality.ao and ao_taps > 0
  bool checker = false;           // some material has pattern = "checker"
  std::vector<std::string> library;  // library names (sd*, op*, dom*, ...) the map references, sorted, each once

  int point_lights() const;
  int directional_lights() const;
  bool operator==(const FeatureSet&) const = default;
};

// The features of `scene` whose map (with everything it includes) is
// `map_glsl`. Animated values count: a reflectivity keyed above 0 makes the
// scene reflective, since the shader must be able to show it.
FeatureSet derive_features(const Scene& scene, std::string_view map_glsl);
// The same from an already scanned name list (the viewer re-derives every
// frame, after panel edits, without rescanning the GLSL).
FeatureSet derive_features(const Scene& scene, std::vector<std::string> library);

// Identifiers that look like library functions (a kind prefix, "sd", "ud",
// "op", "dom" or "noise", followed by an upper-case letter or digit) in
// `glsl`, comments skipped,
// sorted and unique. Lexical: a name in an inactive #if group counts too,
// which only ever keeps more code than needed.
std::vector<std::string> referenced_library_names(std::string_view glsl);

// One line for logs and --verbose, e.g. "lights: point, directional;
// reflections: 2 bounces; shadows; ao; checker; uses: opUnion sdPlane sdSphere".
std::string describe(const FeatureSet& f);

}  // namespace ms
