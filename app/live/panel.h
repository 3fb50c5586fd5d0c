// The viewer's Dear ImGui panel: frame times (graph + median over the last
// second), time, debug view, quality toggles and preset, camera, lights,
// materials, sky and the scene's own ranged uniforms. Uniform values apply
// on the next frame; values that are #defines (quality) ask for a
// re-assembly when a widget is released, so a drag does not recompile per
// frame. Writing to the TOML is a request served by the loop.
#pragma once
#include <string>
#include <vector>

#include "live/session.h"
#include "live/view_state.h"
#include "scene/quality_fields.h"

namespace ms {
struct GlInfo;
}

namespace ms::live {

void draw_panel(ViewState& state, Session& session, const GlInfo& gl);

// Where the panel first opens in a window of `width` x `height` pixels: at
// most 40 % of the width, and collapsed to its title bar in a small window
// (under 960x540), so a 640x360 image stays visible; a click opens it.
struct PanelLayout {
  float width = 380.0f;
  float height = 0.0f;
  bool collapsed = false;
};
PanelLayout panel_layout(float width, float height);

// How the panel shows one [quality] key (scene/quality_fields.h), from its
// type and range alone, so a key added there appears here: a checkbox; a
// slider over a closed range (logarithmic past three decades; an open end
// stays inside); or a drag from the range's lower end, unbounded above.
// Every value a widget can set is one the scene loader accepts.
struct QualityWidget {
  enum Kind { checkbox, slider, drag } kind = checkbox;
  bool integer = false;
  double lo = 0.0, hi = 0.0;  // slider: both ends; drag: lo (and hi = the type's largest)
  bool log = false;
};
QualityWidget quality_widget(const Field<Quality>& f);

// The scene parameters' current values as GLSL declarations with their
// annotations, ready to paste back into the map file.
std::string param_declarations(const std::vector<SceneParam>& params);

}  // namespace ms::live
