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

// A box on the window, in pixels from its top left.
struct OverlayRect {
  float x = 0.0f, y = 0.0f, w = 0.0f, h = 0.0f;
  bool empty() const { return w <= 0.0f || h <= 0.0f; }
  bool overlaps(const OverlayRect& o) const {
    return !empty() && !o.empty() && x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
};
// Where the key help (help_w x help_h) goes in a window of width x height:
// centred, unless that covers the status box (samples, pause, debug view)
// at the top right, `status` (empty when none is shown); then below that
// box, or if it does not fit there, to its left; never over it.
OverlayRect help_rect(float width, float height, const OverlayRect& status, float help_w, float help_h);

// Debug views are shown as values (no exposure, tone map or sRGB encode:
// live/session.h display_exposure()), so the legend is the shader's ramp as
// it is: the heat map's colour for a step count, the ramp of
// sdf_shaders/aov.glsl (mirrored in render/aov.h).
glm::vec3 heat_legend_color(float steps);
// The distances the depth view's legend labels, ascending, from 0 to max_dist.
std::vector<float> depth_legend_ticks(float max_dist);

}  // namespace ms::live
