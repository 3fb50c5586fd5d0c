// Does a scene's [bounds] hold everything map() draws? Rays march map()
// only inside the bounds, so geometry that pokes out (a grown shape, a
// slider pushed too far, an animation) is cut off without a word. This
// samples map() at points on the bounds' surface in one small pass
// (sdf_shaders/bounds_probe.glsl: a 64 x 64 grid per box face, or as many
// points spiralled over a sphere) and reports where the field is negative
// there, ignoring points inside a declared plane's solid side. Called by
// `render` (pipeline/bounds_report.h), `bench` and the viewer; needs a current GL
// context.
//
//   const BoundsCheck c = check_bounds(posed_scene, assemble_opts, set_uniforms);
//   if (!c.ok()) std::fprintf(stderr, "%s\n", bounds_warning(scene_file, c).c_str());
#pragma once
#include <string>

#include <glm/vec3.hpp>

#include "render/frame.h"
#include "render/program_cache.h"
#include "scene/scene.h"
#include "shader/assemble.h"

namespace ms {

struct BoundsCheck {
  int samples = 0;          // points on the surface evaluated (0: no bounds to check)
  int negative = 0;         // of those, where map() < 0: geometry crosses the surface there
  float min_value = 0.0f;   // the most negative map() value found
  glm::vec3 worst{0.0f};    // where
  bool ok() const { return negative == 0; }
};

// The check for `scene` as posed (time, animation), its shader assembled
// with `opts` (the caller's specialization and defines) plus BOUNDS_PROBE;
// `set_uniforms` sets what the scene's main pass gets (time, the viewer's
// slider values). A scene without bounds, or with [quality] bounds = false,
// gives samples = 0. `cache`, when given, keeps the probe's program between
// calls (the viewer checks again whenever a slider moves). Throws ms::Error
// if the probe does not compile (the main pass would not either).
BoundsCheck check_bounds(const Scene& scene, AssembleOptions opts, const UniformFn& set_uniforms,
                         ProgramCache* cache = nullptr);

// One line without the "marchstudio: " prefix: "<file>: warning: map() is
// negative on the [bounds] surface at 12 of 24576 points (down to -0.2 at
// (1, 0.5, 0)): what crosses it is cut off; grow [bounds]". Empty when ok.
std::string bounds_warning(const std::string& scene_file, const BoundsCheck& c);

}  // namespace ms
