#include "live/panel.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <type_traits>
#include <variant>
#include <string>

#include <imgui.h>

#include "gl/context.h"
#include "live/key_bindings.h"
#include "scene/quality.h"
#include "shader/assemble.h"

namespace ms::live {

QualityWidget quality_widget(const Field<Quality>& f) {
  QualityWidget w;
  if (std::holds_alternative<bool Quality::*>(f.member)) return w;
  w.integer = std::holds_alternative<int Quality::*>(f.member);
  const Range& r = f.range;
  // An open end moves inside by one step of the widget's type.
  const double max = w.integer ? static_cast<double>(INT_MAX) : static_cast<double>(FLT_MAX);
  const auto inside = [&](double x, double toward) {
    return w.integer ? x + (toward > x ? 1.0 : -1.0)
                     : static_cast<double>(std::nextafter(static_cast<float>(x), static_cast<float>(toward)));
  };
  w.lo = std::isfinite(r.lo) ? (r.lo_open ? inside(r.lo, max) : r.lo) : -max;
  if (std::isfinite(r.lo) && std::isfinite(r.hi)) {
    w.kind = QualityWidget::slider;
    w.hi = r.hi_open ? inside(r.hi, r.lo) : r.hi;
    w.log = w.lo > 0 && w.hi / w.lo >= 1000.0;
  } else {
    w.kind = QualityWidget::drag;
    w.hi = max;
  }
  return w;
}

namespace {

// A quality value is a #define: re-assemble once the widget lets go.
void define_changed(ViewState& s) {
  if (ImGui::IsItemDeactivatedAfterEdit()) s.want_reassemble = true;
}

void frame_times(ViewState& s) {
  const double gpu = s.gpu_ms.median(s.now), cpu = s.cpu_ms.median(s.now), frame = s.frame_ms.median(s.now);
  // Medians over the last second: one slow frame does not move them.
  ImGui::Text("GPU %.2f ms   CPU %.2f ms", gpu, cpu);
  ImGui::Text("frame %.2f ms (%.1f fps)", frame, frame > 0 ? 1000.0 / frame : 0.0);
  const std::vector<float> g = s.gpu_ms.values(), f = s.frame_ms.values();
  const float width = ImGui::GetContentRegionAvail().x;
  if (!g.empty()) ImGui::PlotLines("##gpu", g.data(), static_cast<int>(g.size()), 0, "GPU ms", 0.0f, FLT_MAX, ImVec2(width, 50));
  if (!f.empty()) ImGui::PlotLines("##frame", f.data(), static_cast<int>(f.size()), 0, "frame ms", 0.0f, FLT_MAX, ImVec2(width, 50));
}

void time_and_view(ViewState& s, Session& session) {
  ImGui::Checkbox("paused (Space)", &s.paused);
  float t = static_cast<float>(s.time);
  const float earliest = static_cast<float>(std::min(0.0, s.start_time));  // a negative start stays reachable
  if (ImGui::DragFloat("time (s)", &t, 0.01f, earliest, 1e6f, "%.3f")) s.time = std::max(earliest, t);
  ImGui::SliderFloat("speed", &s.speed, 0.0f, 4.0f, "%.2fx");
  ImGui::SliderFloat("render scale", &s.render_scale, 0.25f, 1.0f, "%.2f");
  ImGui::SliderFloat("exposure", &session.scene().render.exposure, 0.05f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  if (session.shadertoy()) return;
  if (ImGui::BeginCombo("debug view", debug_view_name(s.debug_view))) {
    for (int v = 0; v < kDebugViews; ++v)
      if (ImGui::Selectable((std::to_string(v) + " " + debug_view_name(v)).c_str(), v == s.debug_view)) s.debug_view = v;
    ImGui::EndCombo();
  }
}

// Typed-in values are clamped too: the panel never sets a value the file could not hold.
ImGuiSliderFlags slider_flags(const QualityWidget& w) {
  return ImGuiSliderFlags_AlwaysClamp | (w.log ? ImGuiSliderFlags_Logarithmic : 0);
}

void quality(ViewState& s, Session& session) {
  Quality& q = session.scene().quality;
  // The presets `render --preset` has (scene/quality.h), by the same names.
  if (ImGui::BeginCombo("preset", session.preset().c_str())) {
    for (const std::string& name : quality_preset_names())
      if (ImGui::Selectable(name.c_str(), name == session.preset())) {
        session.set_preset(name);
        s.want_reassemble = true;
      }
    ImGui::EndCombo();
  }
  for (const Field<Quality>& f : kQualityFields) {
    const QualityWidget w = quality_widget(f);
    const std::string label(f.key);
    std::visit(
        [&](auto member) {
          auto& v = q.*member;
          using V = std::remove_reference_t<decltype(v)>;
          if constexpr (std::is_same_v<V, bool>) {
            if (ImGui::Checkbox(label.c_str(), &v)) s.want_reassemble = true;
            return;
          } else if constexpr (std::is_same_v<V, int>) {
            const int lo = static_cast<int>(w.lo), hi = static_cast<int>(std::min<double>(w.hi, INT_MAX));
            if (w.kind == QualityWidget::slider)
              ImGui::SliderInt(label.c_str(), &v, lo, hi, "%d", slider_flags(w));
            else
              ImGui::DragInt(label.c_str(), &v, 1.0f, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
          } else if constexpr (std::is_same_v<V, float>) {
            const float lo = static_cast<float>(w.lo), hi = static_cast<float>(std::min<double>(w.hi, FLT_MAX));
            if (w.kind == QualityWidget::slider)
              ImGui::SliderFloat(label.c_str(), &v, lo, hi, "%.3f", slider_flags(w));
            else
              ImGui::DragFloat(label.c_str(), &v, std::max(0.001f, std::abs(v) * 0.01f), lo, hi, "%.4g",
                               ImGuiSliderFlags_AlwaysClamp);
          } else {
            ImGui::DragFloat3(label.c_str(), &v.x, 0.01f);
          }
          define_changed(s);  // a #define: re-assembled when the widget is let go
        },
        f.member);
  }
}

void camera(ViewState& s, const Session& session) {
  ImGui::DragFloat3("position", &s.camera.position.x, 0.01f);
  ImGui::DragFloat3("target", &s.camera.target.x, 0.01f);
  ImGui::SliderFloat("fov", &s.camera.fov_deg, 1.0f, 150.0f, "%.1f deg");
  if (ImGui::Button("reset (R)")) s.camera = s.scene_camera;
  if (session.has_toml()) {
    ImGui::SameLine();
    if (ImGui::Button("write camera to TOML (C)")) s.want_write_camera = true;
  }
}

void lights(Scene& scene) {
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    Light& l = scene.lights[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::Text("light %zu (%s)", i, l.kind == LightKind::point ? "point" : "directional");
    if (l.kind == LightKind::point) {
      ImGui::DragFloat3("position", &l.position.x, 0.02f);
      ImGui::DragFloat3("attenuation", &l.attenuation.x, 0.001f, 0.0f, 10.0f, "%.4f");
    } else {
      ImGui::DragFloat3("direction", &l.direction.x, 0.01f, -1.0f, 1.0f);
    }
    ImGui::ColorEdit3("color", &l.color.x, ImGuiColorEditFlags_Float);
    ImGui::SliderFloat("intensity", &l.intensity, 0.0f, 20.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("size", &l.size, 0.0f, l.kind == LightKind::point ? 5.0f : 20.0f, "%.3f");
    ImGui::PopID();
  }
}

void materials(Scene& scene) {
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    Material& m = scene.materials[i];
    ImGui::PushID(1000 + static_cast<int>(i));
    if (ImGui::TreeNode("material", "%s (MAT id %zu)", m.name.c_str(), i)) {
      ImGui::ColorEdit3("color", &m.color.x, ImGuiColorEditFlags_Float);
      ImGui::SliderFloat("ambient", &m.ambient, 0.0f, 2.0f);
      ImGui::SliderFloat("diffuse", &m.diffuse, 0.0f, 2.0f);
      ImGui::SliderFloat("specular", &m.specular, 0.0f, 2.0f);
      ImGui::SliderFloat("shininess", &m.shininess, 1.0f, 1024.0f, "%.1f", ImGuiSliderFlags_Logarithmic);
      ImGui::SliderFloat("reflectivity", &m.reflectivity, 0.0f, 1.0f);
      if (m.pattern == Pattern::checker) {
        ImGui::ColorEdit3("color2", &m.color2.x, ImGuiColorEditFlags_Float);
        ImGui::SliderFloat("pattern_scale", &m.pattern_scale, 0.01f, 10.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
        ImGui::DragFloat3("pattern_velocity", &m.pattern_velocity.x, 0.01f);
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

void sky(Scene& scene) {
  ImGui::ColorEdit3("horizon", &scene.sky.horizon.x, ImGuiColorEditFlags_Float);
  ImGui::ColorEdit3("zenith", &scene.sky.zenith.x, ImGuiColorEditFlags_Float);
  ImGui::ColorEdit3("ambient", &scene.sky.ambient.x, ImGuiColorEditFlags_Float);
}

void params(Session& session) {
  for (SceneParam& p : session.params()) {
    if (p.color) {
      ImGui::ColorEdit3(p.name.c_str(), p.value.data(), ImGuiColorEditFlags_Float);
    } else if (p.is_int) {
      int v = static_cast<int>(p.value[0]);
      if (ImGui::SliderInt(p.name.c_str(), &v, static_cast<int>(p.lo), static_cast<int>(p.hi))) p.value[0] = static_cast<float>(v);
    } else {
      ImGui::SliderScalarN(p.name.c_str(), ImGuiDataType_Float, p.value.data(), p.components, &p.lo, &p.hi, "%.3f");
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) p.value = p.initial;  // right click: back to the file's
  }
  // The values live in GLSL, not the TOML: hand them over as declarations
  // to paste into the map file.
  if (ImGui::Button("copy as GLSL declarations")) ImGui::SetClipboardText(param_declarations(session.params()).c_str());
}

}  // namespace

std::string param_declarations(const std::vector<SceneParam>& params) {
  auto num = [](float v) {  // "-0.5", not glsl_float's "(-0.5)": reads better in a declaration
    std::string s = glsl_float(v);
    return s.front() == '(' ? s.substr(1, s.size() - 2) : s;
  };
  std::string out;
  for (const SceneParam& p : params) {
    std::string value;
    if (p.is_int) {
      value = std::to_string(static_cast<int>(p.value[0]));
    } else if (p.components == 1) {
      value = num(p.value[0]);
    } else {
      value = p.type + "(";
      for (int i = 0; i < p.components; ++i) value += (i ? ", " : "") + num(p.value[i]);
      value += ")";
    }
    const std::string note = p.color ? "color" : "range(" + num(p.lo) + ", " + num(p.hi) + ")";
    out += "uniform " + p.type + " " + p.name + " = " + value + ";  // " + note + "\n";
  }
  return out;
}

PanelLayout panel_layout(float width, float height) {
  PanelLayout l;
  l.width = std::clamp(0.4f * width, 160.0f, 380.0f);
  l.collapsed = width < 960.0f || height < 540.0f;
  l.height = std::max(100.0f, (l.collapsed ? 0.8f : 1.0f) * height - 20.0f);  // its size once opened
  return l;
}

void draw_panel(ViewState& s, Session& session, const GlInfo& gl) {
  const PanelLayout layout = panel_layout(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(layout.width, layout.height), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(layout.collapsed, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (!ImGui::Begin("marchstudio", &s.show_panel)) {
    ImGui::End();
    return;
  }
  Scene& scene = session.scene();
  ImGui::Text("%s  [%s]", scene.name.c_str(), gl.renderer.c_str());
  if (session.error().empty()) ImGui::TextColored(ImVec4(0.5f, 1.0f, 0.5f, 1.0f), "program ok (build %d)", session.generation());
  else ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "last reload failed (see below)");
  if (ImGui::CollapsingHeader("Frame time (medians of the last second)", ImGuiTreeNodeFlags_DefaultOpen))
    frame_times(s);
  if (ImGui::CollapsingHeader("Time and view", ImGuiTreeNodeFlags_DefaultOpen)) time_and_view(s, session);
  // The scene's own knobs first: they are what an artist came to turn.
  if (!session.params().empty() && ImGui::CollapsingHeader("Scene parameters", ImGuiTreeNodeFlags_DefaultOpen))
    params(session);
  if (!session.shadertoy()) {
    if (ImGui::CollapsingHeader("Quality (recompiles)")) quality(s, session);
    if (ImGui::CollapsingHeader("Camera")) camera(s, session);
    if (!scene.lights.empty() && ImGui::CollapsingHeader("Lights")) lights(scene);
    if (ImGui::CollapsingHeader("Materials")) materials(scene);
    if (ImGui::CollapsingHeader("Sky")) sky(scene);
  }
  if (session.has_toml()) {
    if (ImGui::Button("write values to TOML (Ctrl+S)")) s.want_write_values = true;
    ImGui::SameLine();
    if (ImGui::Button("revert (F5)")) s.want_disk_reload = true;
  }
  if (ImGui::CollapsingHeader("Keys")) {
    for (const char* const* line = key_help(); *line; ++line) ImGui::TextUnformatted(*line);
  }
  ImGui::End();
}

}  // namespace ms::live
