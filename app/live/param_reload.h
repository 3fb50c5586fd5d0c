// A scene's own uniforms, shown as sliders in the viewer's panel: parsed by
// shader/scene_params.h (where --uniform also sets their values); here what
// only the viewer needs: a slider keeps its value across a reload.
#pragma once
#include <vector>

#include "shader/scene_params.h"

namespace ms::live {

using ms::parse_scene_params;
using ms::SceneParam;

// After a reload: a parameter whose type and initializer did not change keeps
// the value the user set; an edited initializer wins (the file changed).
void carry_over_values(std::vector<SceneParam>& fresh, const std::vector<SceneParam>& old);

}  // namespace ms::live
