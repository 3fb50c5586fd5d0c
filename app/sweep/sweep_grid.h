// The configurations `marchstudio sweep` measures: the presets (the textbook
// baseline among them) and variations of the quality settings around the
// default preset. Pure: no GL, no files. docs/speed-vs-error.md.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace ms {

// One row of a sweep.
struct SweepConfig {
  std::string name;  // unique label: "balanced", "omega=1.5", "steps=64 tol=fp1 omega=1.25 marched"
  std::string axis;  // what it varies: "preset", "max_steps", "tolerance", "omega", "geometry",
                     // "max_distance", "shadow", "ao_taps", "bounces", "normal_eps", "tracer" (full grid)
  Quality quality;
  // Library tunables (#defines before prelude.glsl): NORMAL_EPS_SCALE,
  // NORMAL_EPS_MIN, SHADOW_ESTIMATOR, SHADOW_MAX_STEP. Empty: the defaults.
  std::vector<std::pair<std::string, std::string>> tunables;
  // A scene graph's pruning cells (axis "cell_size"); 0: sized from the node count.
  float cell_size = 0.0f;
};

enum class SweepGrid { quick, full };

// "quick" | "full"; throws bad_input (key --grid) otherwise.
SweepGrid parse_sweep_grid(const std::string& name);
const char* sweep_grid_name(SweepGrid g);

// The quality a preset row uses for a scene whose own [quality] is `scene`:
// with_preset(), except that for "textbook" and "reference" the settings
// that define the tracer (steps, tolerance, epsilon, omega, max distance,
// bounds, planes; and shadow steps for reference) are the preset's even
// when the scene file sets them, so the baseline and the reference are the
// same on every scene. Shading settings (AO taps, bounces, the Lipschitz
// bound) stay the scene's.
Quality sweep_preset_quality(const Quality& scene, const std::string& preset);

// The rows, in order: the presets (textbook, fast, balanced, reference),
// then one-at-a-time variations of preset `base` over every axis; `full`
// adds a factorial over max steps x tolerance x omega x geometry (marched
// planes and no bounds, or analytic planes and bounds). Rows whose settings
// repeat an earlier row are left out.
std::vector<SweepConfig> sweep_grid(const Quality& scene, SweepGrid grid, const std::string& base = "balanced");

// A scene graph's rows of the "cell_size" axis: preset `base` with cells
// of half, and twice, `auto_side` (the pruning grid's cells as planned
// from the node count); none when auto_side is 0 (no grid).
std::vector<SweepConfig> cell_size_rows(const Quality& scene, float auto_side, const std::string& base = "balanced");

// The tunable's value in `c`, or `fallback` (the library default) when unset.
std::string tunable(const SweepConfig& c, const std::string& name, const std::string& fallback);

}  // namespace ms
