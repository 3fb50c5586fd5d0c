// Quality presets, defined here and only here (docs/scene-format.md,
// [quality]). A scene picks one with `[quality] preset = "..."` (default
// "balanced"); render/bench/sweep --preset replace the file's choice; keys
// the file sets explicitly override whichever preset applies.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace ms {

// "fast", "balanced", "reference", "textbook", in that order.
const std::vector<std::string>& quality_preset_names();

// The preset's values. `balanced` is Quality{}; `textbook` is the baseline
// every sweep shows: plain sphere tracing of the whole field (planes
// marched), no bounds, fixed epsilon 1e-4, 255 steps, max distance 100,
// omega 1. Throws bad_input (key `key`) naming an unknown preset, with a
// did-you-mean.
Quality preset_quality(std::string_view name, const std::string& key = "--preset");

// `q` re-based on preset `name`: the preset's values with q's explicit keys
// (Quality::explicit_keys) copied over them; preset = name.
Quality with_preset(const Quality& q, std::string_view name, const std::string& key = "--preset");

}  // namespace ms
