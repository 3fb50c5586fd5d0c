#include "live/live_values.h"

#include <algorithm>
#include <cmath>

#include "scene/animation.h"
#include "shader/specialize.h"

namespace ms::live {

void LiveValues::built(const Scene& scene, std::vector<std::string> live) {
  any_ = true;
  scene_ = scene;
  live_ = std::move(live);
}

std::optional<std::vector<std::string>> LiveValues::rebuild(const Scene& now, bool dragging) const {
  if (!any_) return std::nullopt;
  std::vector<std::string> changed = folded_differences(scene_, now);
  // A live value (or a whole live entry) shows through its uniforms already.
  const auto shown = [&](const std::string& name) {
    return std::any_of(live_.begin(), live_.end(), [&](const std::string& l) {
      return l == name || (name.rfind(l, 0) == 0 && name.size() > l.size() && name[l.size()] == '.');
    });
  };
  if (dragging) {
    changed.erase(std::remove_if(changed.begin(), changed.end(), shown), changed.end());
    if (changed.empty()) return std::nullopt;
    std::vector<std::string> next = live_;
    next.insert(next.end(), changed.begin(), changed.end());
    return next;
  }
  if (live_.empty() && changed.empty()) return std::nullopt;
  return std::vector<std::string>{};
}

std::string live_names(const std::vector<std::string>& live) {
  std::string out;
  for (const std::string& l : live) out += (out.empty() ? "" : ",") + l;
  return out.empty() ? "none" : out;
}

std::string uniform_tables(const std::string& text) {
  std::vector<std::string> out;
  for (const char* t : {"LIGHT", "MATERIAL", "SKY"})
    if (text.find(std::string("#define ") + t + "_UNIFORMS 1\n") != std::string::npos)
      out.push_back(t == std::string("LIGHT") ? "lights" : t == std::string("MATERIAL") ? "materials" : "sky");
  // The single live values of folded tables (shader/specialize.cpp live_uniform).
  const std::string mark = "// live value: ";
  for (size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 1)) {
    const size_t from = at + mark.size();
    out.push_back(text.substr(from, text.find('\n', from) - from));
  }
  return live_names(out);
}

bool fuse_frame(const Scene& scene, int accumulate, int debug_view, bool shadertoy) {
  const int target = accumulate < 0 ? std::max(1, scene.render.spp) : accumulate;
  return !shadertoy && debug_view == 0 && !scene.bloom.enabled && target == 1 && scene.render.spp <= 1;
}

bool ScriptedDrag::apply(Scene& scene, std::vector<SceneParam>& params, long frame) {
  if (first < 0 || frame < first || frame > last) return false;
  int arity = 0;
  auto param = std::find_if(params.begin(), params.end(), [&](const SceneParam& p) { return p.name == target; });
  if (uniform && param == params.end()) return true;  // a reload dropped it: the drag goes on over nothing
  if (frame == first) {
    if (uniform) std::copy_n(param->value.begin(), 3, from_.begin());
    else target_value(scene, target, &from_, &arity, false);
  }
  const double u = last > first ? static_cast<double>(frame - first) / static_cast<double>(last - first) : 1.0;
  std::array<double, 3> v{};
  for (int c = 0; c < 3; ++c) v[c] = from_[c] + (to[c] - from_[c]) * u;
  if (!uniform) {
    target_value(scene, target, &v, &arity, true);
    return true;
  }
  // As the panel's slider sets it: an int uniform takes whole values.
  for (int c = 0; c < std::min(param->components, 3); ++c)
    param->value[c] = static_cast<float>(param->is_int ? std::round(v[c]) : v[c]);
  return true;
}

}  // namespace ms::live
