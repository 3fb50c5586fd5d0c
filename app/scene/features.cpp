#include "scene/features.h"

#include <algorithm>
#include <cctype>

namespace ms {
namespace {

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The kinds of guarded library functions (docs/shader-library.md): signed
// and unsigned distances (sd, sd2, ud, ud2), operators (op), domain
// operators (dom) and noises (noise).
constexpr std::string_view kLibraryPrefixes[] = {"sd", "ud", "op", "dom", "noise"};

// True when material i's reflectivity is keyed above 0 at some time.
bool animated_reflective(const Scene& scene, size_t i) {
  const std::string target = "materials[" + std::to_string(i) + "].reflectivity";
  for (const AnimationTrack& t : scene.animation)
    if (t.target == target && std::any_of(t.values.begin(), t.values.end(), [](double v) { return v > 0.0; }))
      return true;
  return false;
}

}  // namespace

int FeatureSet::point_lights() const {
  return static_cast<int>(std::count(lights.begin(), lights.end(), LightKind::point));
}

int FeatureSet::directional_lights() const {
  return static_cast<int>(std::count(lights.begin(), lights.end(), LightKind::directional));
}

std::vector<std::string> referenced_library_names(std::string_view glsl) {
  std::vector<std::string> names;
  size_t i = 0;
  const size_t n = glsl.size();
  while (i < n) {
    if (glsl.compare(i, 2, "//") == 0) {
      i = glsl.find('\n', i);
      if (i == std::string_view::npos) break;
      continue;
    }
    if (glsl.compare(i, 2, "/*") == 0) {
      i = glsl.find("*/", i + 2);
      if (i == std::string_view::npos) break;
      i += 2;
      continue;
    }
    if (!is_word(glsl[i])) {
      ++i;
      continue;
    }
    const size_t b = i;
    while (i < n && is_word(glsl[i])) ++i;
    const std::string_view w = glsl.substr(b, i - b);
    // A number such as "1e5" never starts with a prefix, so no digit check.
    for (std::string_view prefix : kLibraryPrefixes)
      if (w.size() > prefix.size() && w.substr(0, prefix.size()) == prefix &&
          (std::isupper(static_cast<unsigned char>(w[prefix.size()])) ||
           std::isdigit(static_cast<unsigned char>(w[prefix.size()])))) {
        names.emplace_back(w);
        break;
      }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

FeatureSet derive_features(const Scene& scene, std::vector<std::string> library) {
  const Quality& q = scene.quality;
  FeatureSet f;
  for (const Light& l : scene.lights) f.lights.push_back(l.kind);
  bool mirror = false;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    mirror = mirror || m.reflectivity > 0.0f || animated_reflective(scene, i);
    f.checker = f.checker || m.pattern == Pattern::checker;
  }
  f.reflective = mirror && q.reflections && q.bounces > 0;
  f.max_bounces = f.reflective ? q.bounces : 0;
  f.shadows = q.shadows && q.shadow_steps > 0 && !scene.lights.empty();
  f.ao = q.ao && q.ao_taps > 0;
  f.library = std::move(library);
  return f;
}

FeatureSet derive_features(const Scene& scene, std::string_view map_glsl) {
  return derive_features(scene, referenced_library_names(map_glsl));
}

std::string describe(const FeatureSet& f) {
  std::string s = "lights:";
  if (f.lights.empty()) s += " none";
  for (size_t i = 0; i < f.lights.size(); ++i)
    s += std::string(i ? ", " : " ") + (f.lights[i] == LightKind::point ? "point" : "directional");
  s += f.reflective ? "; reflections: " + std::to_string(f.max_bounces) + " bounce" + (f.max_bounces > 1 ? "s" : "")
                    : "; no reflections";
  s += f.shadows ? "; shadows" : "; no shadows";
  s += f.ao ? "; ao" : "; no ao";
  s += f.checker ? "; checker" : "; no checker";
  s += "; uses:";
  for (const std::string& name : f.library) s += " " + name;
  if (f.library.empty()) s += " nothing";
  return s;
}

}  // namespace ms
