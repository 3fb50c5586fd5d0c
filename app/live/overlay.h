// What the viewer draws over the image with Dear ImGui, apart from the
// panel: the compile error box (file:line: message), the steps heat-map
// legend, the debug view's name, transient messages and the key help.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "live/session.h"
#include "live/view_state.h"

namespace ms::live {

void draw_overlay(const ViewState& state, const Session& session);

// Debug views are shown as values (no exposure, tone map or sRGB encode:
// live/session.h display_exposure()), so the legend is the shader's ramp as
// it is: the heat map's colour for a step count, the ramp of
// sdf_shaders/aov.glsl (mirrored in render/aov.h).
glm::vec3 heat_legend_color(float steps);
// The distances the depth view's legend labels, ascending, from 0 to max_dist.
std::vector<float> depth_legend_ticks(float max_dist);

}  // namespace ms::live
