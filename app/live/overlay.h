// What the viewer draws over the image with Dear ImGui, apart from the
// panel: the compile error box (file:line: message), the steps heat-map
// legend, the debug view's name, transient messages and the key help.
#pragma once
#include <glm/vec3.hpp>

#include "live/session.h"
#include "live/view_state.h"

namespace ms::live {

void draw_overlay(const ViewState& state, const Session& session);

// The heat map's colour on screen for a step count: the ramp of
// sdf_shaders/aov.glsl (mirrored in render/aov.h) through the same exposure,
// tone map and sRGB encode as the post pass, so the legend matches the image.
glm::vec3 heat_legend_color(float steps, float exposure, Tonemap tonemap);
// The same for a position x in [0,1] along the legend.
glm::vec3 heat_display_color(float x, float exposure, Tonemap tonemap);

}  // namespace ms::live
