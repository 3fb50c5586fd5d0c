#include "scene/quality.h"

#include <algorithm>
#include <variant>

#include "core/error.h"
#include "scene/quality_fields.h"
#include "core/suggest.h"

namespace ms {

const std::vector<std::string>& quality_preset_names() {
  static const std::vector<std::string> names = {"fast", "balanced", "reference", "textbook"};
  return names;
}

// The values were chosen from `marchstudio sweep` fronts (docs/speed-vs-error.md).
Quality preset_quality(std::string_view name, const std::string& key) {
  Quality q;  // balanced
  if (name == "fast") {
    q.max_steps = 96;
    q.hit_tolerance = 0.5f;
    q.shadow_steps = 24;
    q.ao_taps = 3;
  } else if (name == "reference") {
    // Converged: many steps, a fifth of balanced's footprint tolerance and a
    // tenth of its absolute floor, no relaxation. Tighter than the textbook's
    // fixed 1e-4 up to t = 0.05 / pixel angle (43 at 1280x720, fov 45).
    q.max_steps = 4000;
    q.hit_tolerance = 0.002f;
    q.hit_epsilon = 1e-5f;
    q.omega = 1.0f;
    q.shadow_steps = 512;
  } else if (name == "textbook") {
    q.max_steps = 255;
    q.max_distance = 100.0f;
    q.hit_tolerance = 0.0f;
    q.hit_epsilon = 1e-4f;
    q.omega = 1.0f;
    q.bounds = false;
    q.analytic_planes = false;
  } else if (name != "balanced") {
    std::vector<std::string_view> names(quality_preset_names().begin(), quality_preset_names().end());
    std::string hint = did_you_mean(name, names);
    fail_input("unknown quality preset '" + std::string(name) + "'", {}, 0, key,
               hint.empty() ? "use fast, balanced, reference or textbook" : hint);
  }
  q.preset = std::string(name);
  return q;
}

Quality with_preset(const Quality& q, std::string_view name, const std::string& key) {
  Quality out = preset_quality(name, key);
  for (const Field<Quality>& f : kQualityFields) {
    if (std::find(q.explicit_keys.begin(), q.explicit_keys.end(), f.key) == q.explicit_keys.end()) continue;
    std::visit([&](auto member) { out.*member = q.*member; }, f.member);
  }
  out.explicit_keys = q.explicit_keys;
  if (q.lipschitz_derived && std::find(q.explicit_keys.begin(), q.explicit_keys.end(), "lipschitz") == q.explicit_keys.end()) {
    out.lipschitz = q.lipschitz;  // the graph's bound, not a preset's guess
    out.lipschitz_derived = true;
  }
  return out;
}

}  // namespace ms
