#include "live/overlay.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>

#include "live/input.h"
#include "render/aov.h"

namespace ms::live {
namespace {

float display(float c, Tonemap tm) {  // post.frag for 8-bit output
  c = std::max(c, 0.0f);
  if (tm == Tonemap::reinhard) c = c / (1.0f + c);
  if (tm == Tonemap::aces) c = std::clamp((c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f), 0.0f, 1.0f);
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

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

// Inside the status window, under the view's name.
void draw_legend(const Scene& scene) {
  ImGui::Separator();
  ImGui::TextUnformatted("primary ray steps (log scale)");
  const float w = 240.0f, h = 16.0f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  constexpr int kSlices = 64;
  for (int i = 0; i < kSlices; ++i) {
    const float x0 = static_cast<float>(i) / kSlices, x1 = static_cast<float>(i + 1) / kSlices;
    dl->AddRectFilled(ImVec2(p.x + x0 * w, p.y), ImVec2(p.x + x1 * w + 1.0f, p.y + h),
                      to_imgui(heat_display_color(0.5f * (x0 + x1), scene.render.exposure, scene.render.tonemap)));
  }
  // Ticks where the ramp's stops are (render/aov.h mirrors the shader's scale).
  const int ticks[] = {0, 3, 15, 63, 255};
  for (int s : ticks) {
    const float x = p.x + steps_heat_position(static_cast<float>(s)) * w;
    dl->AddLine(ImVec2(x, p.y + h), ImVec2(x, p.y + h + 4.0f), IM_COL32_WHITE);
    const std::string label = s == 255 ? "255+" : std::to_string(s);
    const float tw = ImGui::CalcTextSize(label.c_str()).x;
    dl->AddText(ImVec2(std::clamp(x - tw * 0.5f, p.x, p.x + w - tw), p.y + h + 5.0f), IM_COL32_WHITE,
                label.c_str());
  }
  ImGui::Dummy(ImVec2(w, h + 5.0f + ImGui::GetTextLineHeight()));
  ImGui::Text("MAX_STEPS = %d (misses count too)", scene.quality.max_steps);
}

}  // namespace

glm::vec3 heat_display_color(float x, float exposure, Tonemap tonemap) {
  const glm::vec3 lin = heat_ramp(x) * exposure;
  return {display(lin.r, tonemap), display(lin.g, tonemap), display(lin.b, tonemap)};
}

glm::vec3 heat_legend_color(float steps, float exposure, Tonemap tonemap) {
  return heat_display_color(steps_heat_position(steps), exposure, tonemap);
}

void draw_overlay(const ViewState& s, const Session& session) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const int view = session.compiled_debug_view();
  if (view > 0 || s.paused) {
    ImGui::SetNextWindowPos(ImVec2(size.x - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("##view", nullptr, kOverlayFlags);
    if (view > 0) ImGui::Text("debug view %d: %s", view, debug_view_name(view));
    if (s.paused) ImGui::Text("paused at t = %.3f s", s.time);
    if (view == 1) draw_legend(session.scene());
    ImGui::End();
  }
  if (!session.error().empty()) draw_error(session.error(), session.error_log(), session.generation() > 0);
  if (!s.message.empty() && s.now < s.message_until) {
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 10.0f - (session.error().empty() ? 0.0f : 90.0f)),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("##message", nullptr, kOverlayFlags);
    ImGui::TextUnformatted(s.message.c_str());
    ImGui::End();
  }
  if (s.show_help) {
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("##help", nullptr, kOverlayFlags);
    for (const char* const* line = key_help(); *line; ++line) ImGui::TextUnformatted(*line);
    ImGui::End();
  }
}

}  // namespace ms::live
