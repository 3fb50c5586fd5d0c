// Quality presets for the viewer, defined here and only here (documented in
// docs/viewer.md). A preset scales the scene file's own [quality] values, so
// "balanced" is exactly what `render` would use.
#pragma once
#include <string>

#include "scene/scene.h"

namespace ms::live {

enum class QualityPreset { fast, balanced, reference };

//              max_steps  shadow_steps  hit_tolerance  ao_taps     bounces
// fast         x 1/2      x 1/2         x 2            at most 3   at most 1
// balanced     x 1        x 1           x 1            as is       as is
// reference    x 4        x 4           x 1/4          x 2 (<=64)  as is
// Results stay inside the scene loader's ranges (max_steps >= 1, ao_taps <= 64...).
Quality apply_preset(const Quality& base, QualityPreset preset);

const char* preset_name(QualityPreset p);

}  // namespace ms::live
