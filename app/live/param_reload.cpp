#include "live/param_reload.h"

#include <algorithm>

namespace ms::live {

void carry_over_values(std::vector<SceneParam>& fresh, const std::vector<SceneParam>& old) {
  for (SceneParam& p : fresh) {
    auto it = std::find_if(old.begin(), old.end(), [&](const SceneParam& o) { return o.name == p.name; });
    if (it != old.end() && it->type == p.type && it->initial == p.initial) p.value = it->value;
  }
}

}  // namespace ms::live
