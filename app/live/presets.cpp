#include "live/presets.h"

#include <algorithm>

namespace ms::live {

Quality apply_preset(const Quality& base, QualityPreset preset) {
  Quality q = base;
  switch (preset) {
    case QualityPreset::fast:
      q.max_steps = std::max(1, base.max_steps / 2);
      q.shadow_steps = base.shadow_steps / 2;
      q.hit_tolerance = base.hit_tolerance * 2.0f;
      q.ao_taps = std::min(base.ao_taps, 3);
      q.bounces = std::min(base.bounces, 1);
      break;
    case QualityPreset::balanced:
      break;
    case QualityPreset::reference:
      q.max_steps = std::min(100000, base.max_steps * 4);
      q.shadow_steps = std::min(10000, base.shadow_steps * 4);
      q.hit_tolerance = base.hit_tolerance * 0.25f;
      q.ao_taps = std::min(64, base.ao_taps * 2);
      break;
  }
  return q;
}

const char* preset_name(QualityPreset p) {
  switch (p) {
    case QualityPreset::fast: return "fast";
    case QualityPreset::balanced: return "balanced";
    case QualityPreset::reference: return "reference";
  }
  return "?";
}

}  // namespace ms::live
