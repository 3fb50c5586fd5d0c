#include "live/overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "live/key_bindings.h"
#include "render/aov.h"

namespace ms::live {
namespace {

ImU32 to_imgui(glm::vec3 c) {
  return IM_COL32(static_cast<int>(c.r * 255.0f + 0.5f), static_cast<int>(c.g * 255.0f + 0.5f),
                  static_cast<int>(c.b * 255.0f + 0.5f), 255);
}

constexpr ImGuiWindowFlags kOverlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                           ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;

void draw_error(const std::string& error, const std::string& log, bool have_frame) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(10.0f, size.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(size.x - 20.0f, size.y * 0.5f));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(60, 0, 0, 230));
  ImGui::PushStyleColor(ImGuiCol_Border, IM_COL32(255, 80, 80, 255));
  ImGui::Begin("##error", nullptr, kOverlayFlags);
  // Before the first good build there is no frame to keep.
  ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.6f, 1.0f), "%s",
                     have_frame ? "Reload failed; showing the last good frame"
                                : "Build failed; nothing to show until the shader compiles");
  ImGui::PushTextWrapPos(size.x - 40.0f);
  ImGui::TextUnformatted(error.c_str());
  ImGui::PopTextWrapPos();
  // The first error is above; the rest of the log is one click away, not
  // just "+N more" (a newcomer should not need -v and a terminal).
  const int lines = static_cast<int>(std::count(log.begin(), log.end(), '\n'));
  if (lines > 1 && ImGui::TreeNode("##log", "full compiler log (%d lines)", lines)) {
    const float h = std::min(ImGui::GetTextLineHeightWithSpacing() * (lines + 1), size.y * 0.35f);
    ImGui::BeginChild("##logtext", ImVec2(size.x - 50.0f, h), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(log.c_str());
    ImGui::EndChild();
    ImGui::TreePop();
  }
  ImGui::End();
  ImGui::PopStyleColor(2);
}

// A colour bar with labelled ticks; colour(x) for x in [0,1] along it.
template <class ColourAt, class Tick>
void draw_bar(const char* title, ColourAt colour, const std::vector<Tick>& ticks) {
  ImGui::Separator();
  ImGui::TextUnformatted(title);
  const float w = 240.0f, h = 16.0f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  constexpr int kSlices = 64;
  for (int i = 0; i < kSlices; ++i) {
    const float x0 = static_cast<float>(i) / kSlices, x1 = static_cast<float>(i + 1) / kSlices;
    dl->AddRectFilled(ImVec2(p.x + x0 * w, p.y), ImVec2(p.x + x1 * w + 1.0f, p.y + h), to_imgui(colour(0.5f * (x0 + x1))));
  }
  for (const Tick& t : ticks) {
    const float x = p.x + t.first * w;
    dl->AddLine(ImVec2(x, p.y + h), ImVec2(x, p.y + h + 4.0f), IM_COL32_WHITE);
    const float tw = ImGui::CalcTextSize(t.second.c_str()).x;
    dl->AddText(ImVec2(std::clamp(x - tw * 0.5f, p.x, p.x + w - tw), p.y + h + 5.0f), IM_COL32_WHITE, t.second.c_str());
  }
  ImGui::Dummy(ImVec2(w, h + 5.0f + ImGui::GetTextLineHeight()));
}

// Inside the status window, under the view's name: the steps ramp's stops.
void draw_steps_legend(const Scene& scene) {
  std::vector<std::pair<float, std::string>> ticks;
  for (int s : {0, 3, 15, 63, 255})
    ticks.emplace_back(steps_heat_position(static_cast<float>(s)), s == 255 ? "255+" : std::to_string(s));
  draw_bar("primary ray steps (log scale)", [](float x) { return heat_ramp(x); }, ticks);
  ImGui::Text("MAX_STEPS = %d (misses count too)", scene.quality.max_steps);
}

// The depth view's grey against ray distance, near (white) on the left.
void draw_depth_legend(const Scene& scene) {
  const float far = scene.quality.max_distance;
  std::vector<std::pair<float, std::string>> ticks;
  for (float t : depth_legend_ticks(far)) {
    char label[32];
    std::snprintf(label, sizeof label, "%g", t);
    ticks.emplace_back(1.0f - depth_shade(t, far), label);
  }
  draw_bar("ray distance (log scale, world units)",
           [far](float x) { return glm::vec3(1.0f - x); }, ticks);
  ImGui::Text("black: MAX_DIST = %g, and misses", far);
}

}  // namespace

glm::vec3 heat_legend_color(float steps) { return heat_ramp(steps_heat_position(steps)); }

std::vector<float> depth_legend_ticks(float max_dist) {
  // 0, then 1, 3, 10, 30, ... below max_dist, then max_dist: at most 6.
  std::vector<float> out = {0.0f};
  for (float decade = 1.0f; decade < max_dist; decade *= 10.0f)
    for (float m : {1.0f, 3.0f})
      if (m * decade < max_dist * 0.8f) out.push_back(m * decade);
  while (out.size() > 5) out.erase(out.begin() + 1);  // keep the far ones: near ones crowd at the left
  out.push_back(max_dist);
  return out;
}

OverlayRect help_rect(float width, float height, const OverlayRect& status, float help_w, float help_h) {
  constexpr float kGap = 10.0f;
  const OverlayRect centred{0.5f * (width - help_w), 0.5f * (height - help_h), help_w, help_h};
  if (!centred.overlaps(status)) return centred;
  OverlayRect below = centred;
  below.y = status.y + status.h + kGap;
  if (below.y + help_h <= height - kGap) return below;
  OverlayRect left = centred;
  left.x = status.x - kGap - help_w;
  if (left.x >= kGap) return left;
  below.x = kGap;  // fits nowhere whole: below the box, cut off at the bottom rather than over it
  return below;
}

void draw_overlay(const ViewState& s, const Session& session) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  OverlayRect status;  // the status box, which the help must not cover
  const int view = session.compiled_debug_view();
  const bool accumulating = s.samples_target != 1 && s.samples > 0;
  if (view > 0 || s.paused || accumulating || s.recording_frame >= 0) {
    ImGui::SetNextWindowPos(ImVec2(size.x - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("##view", nullptr, kOverlayFlags);
    if (view > 0) ImGui::Text("debug view %d: %s", view, debug_view_name(view));
    if (s.recording_frame >= 0) ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.3f, 1.0f), "REC frame %d (F9 stops)", s.recording_frame);
    if (s.paused) ImGui::Text("paused at t = %.3f s", s.time);
    if (accumulating && s.samples_target == 0) ImGui::Text("samples %d (no limit; O: up to the target)", s.samples);
    else if (accumulating) ImGui::Text("samples %d / %d%s", s.samples, s.samples_target, s.samples >= s.samples_target ? " (converged)" : "");
    if (view == 1) draw_steps_legend(session.scene());
    if (view == 3) draw_depth_legend(session.scene());
    status = {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x, ImGui::GetWindowSize().y};
    ImGui::End();
  }
  const float above_error = session.error().empty() ? 0.0f : 90.0f;
  const bool bounds = !s.bounds_warning.empty() && !session.shadertoy();
  if (bounds) {
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 10.0f - above_error), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(90, 60, 0, 220));
    ImGui::Begin("##bounds", nullptr, kOverlayFlags);
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "geometry crosses [bounds] and is cut off there: grow [bounds] (details on the terminal)");
    ImGui::End();
    ImGui::PopStyleColor();
  }
  if (!session.error().empty()) draw_error(session.error(), session.error_log(), session.generation() > 0);
  if (!s.message.empty() && s.now < s.message_until) {
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 10.0f - above_error - (bounds ? 34.0f : 0.0f)),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("##message", nullptr, kOverlayFlags);
    ImGui::TextUnformatted(s.message.c_str());
    ImGui::End();
  }
  if (s.show_help) {
    // Its size is last frame's (an auto-resized window's first frame is not shown).
    static ImVec2 help_size(0.0f, 0.0f);
    const OverlayRect r = help_rect(size.x, size.y, status, help_size.x, help_size.y);
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("##help", nullptr, kOverlayFlags);
    for (const char* const* line = key_help(); *line; ++line) ImGui::TextUnformatted(*line);
    help_size = ImGui::GetWindowSize();
    ImGui::End();
  }
}

}  // namespace ms::live
