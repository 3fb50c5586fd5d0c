#include "scene/animation.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <regex>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "scene/graph_animation.h"
#include "scene/schema.h"
#include "core/suggest.h"

namespace ms {
namespace {

constexpr std::string_view kInterpolations[] = {"linear", "smooth"};
// What can be animated: the schema's own fields (scene/schema.h, so the
// ranges have one home) that are floats or vectors, and of [sky] and
// [render] only these. Strings, enums, integers and the environment's
// rotation and intensity cannot: they change the compiled shader.
constexpr std::string_view kAnimatableSky[] = {"horizon", "zenith", "ambient"};
constexpr std::string_view kAnimatableRender[] = {"exposure"};

// A resolved target: where its value lives in one Scene, or why it cannot.
struct Slot {
  float* scalar = nullptr;
  glm::vec3* vec = nullptr;
  Range range;
  std::string canonical;  // "lights[0].intensity", for duplicate checks
  std::string error, hint;
  int arity() const { return vec ? 3 : 1; }
};

template <class T>
bool animatable(const Field<T>& f, Keys only) {
  const bool numeric = std::holds_alternative<float T::*>(f.member) || std::holds_alternative<glm::vec3 T::*>(f.member);
  return numeric && (only.empty() || std::find(only.begin(), only.end(), f.key) != only.end());
}

template <class T, std::size_t N>
Slot member_slot(T& obj, const Field<T> (&table)[N], const std::string& object, const std::string& key,
                 Keys only = {}) {
  Slot s;
  for (const Field<T>& f : table) {
    if (f.key != key || !animatable(f, only)) continue;
    if (auto* m = std::get_if<float T::*>(&f.member)) s.scalar = &(obj.**m);
    else s.vec = &(obj.*std::get<glm::vec3 T::*>(f.member));
    s.range = f.range;
    s.canonical = object + "." + key;
    return s;
  }
  std::vector<std::string_view> keys;
  for (const Field<T>& f : table)
    if (animatable(f, only)) keys.push_back(f.key);
  s.error = quote(key) + " cannot be animated on " + object;
  s.hint = did_you_mean(key, keys);
  if (s.hint.empty()) {
    s.hint = "animatable: ";
    for (std::size_t i = 0; i < keys.size(); ++i) s.hint.append(i ? ", " : "").append(keys[i]);
  }
  return s;
}

// camera.KEY, sky.KEY, render.KEY, lights[i].KEY or materials[i].KEY.
Slot find_slot(const std::string& target, Scene& scene) {
  static const std::regex plain(R"(^(camera|sky|render)\.([A-Za-z_]+)$)");
  static const std::regex indexed(R"(^(lights|materials)\[(\d{1,6})\]\.([A-Za-z_]+)$)");
  std::smatch m;
  // libstdc++'s regex recurses per character: a 50 KB target overflowed the
  // stack (a long fuzz_animation input). No valid target is near this long.
  constexpr std::size_t kMaxTarget = 128;
  if (target.size() <= kMaxTarget && std::regex_match(target, m, plain)) {
    if (m[1] == "camera") return member_slot(scene.camera, kCameraFields, "camera", m[2]);
    if (m[1] == "sky") return member_slot(scene.sky, kSkyFields, "sky", m[2], kAnimatableSky);
    return member_slot(scene.render, kRenderFields, "render", m[2], kAnimatableRender);
  }
  Slot s;
  if (target.size() > kMaxTarget || !std::regex_match(target, m, indexed)) {
    s.error = "unknown animation target " + quote(target);
    s.hint = "expected camera.<key>, lights[<i>].<key>, materials[<i>].<key>, sky.<key>, render.exposure or "
             "graph.<node name>.<key>";
    return s;
  }
  const bool light = m[1] == "lights";
  const std::size_t i = std::stoul(m[2]);
  const std::size_t count = light ? scene.lights.size() : scene.materials.size();
  const std::string object = std::string(m[1]) + "[" + std::to_string(i) + "]";
  if (i >= count) {
    s.error = "animation target " + quote(target) + " names " + object + ", but the scene has " +
              std::to_string(count) + (light ? " light" : " material") + (count == 1 ? "" : "s");
    s.hint = std::string("the ") + std::string(m[1]) + " are numbered from 0 in file order";
    return s;
  }
  if (!light) return member_slot(scene.materials[i], kMaterialFields, object, m[3]);
  Light& l = scene.lights[i];
  s = member_slot(l, kLightFields, object, m[3]);
  // As for the static keys: a value the light's type ignores is a mistake.
  const bool point = l.kind == LightKind::point;
  const std::string key = m[3];
  if (s.error.empty() && (point ? key == "direction" : (key == "position" || key == "attenuation"))) {
    s.error = quote(target) + " does nothing for a " + (point ? "point" : "directional") + " light";
    s.hint = "animate " + object + (point ? ".position" : ".direction") + " instead";
  }
  if (s.error.empty() && !point && key == "size") s.range = Range{0, 180, false, true};
  return s;
}

// One number of a key row, checked like any scene number.
double key_number(const Reader& r, const toml::node& n, const std::string& name, bool is_time, Range range,
                  const std::string& target) {
  double v = 0;
  if (const auto* i = n.as_integer()) v = static_cast<double>(i->get());
  else if (const auto* f = n.as_floating_point()) v = f->get();
  else r.fail(n, name, quote(name) + " must be a number");
  if (!std::isfinite(v)) r.fail(n, name, quote(name) + " must be a finite number, got " + format_number(v));
  // Times too: they reach the shader as a float, as [render] time does.
  if (std::abs(v) > FLT_MAX) r.fail(n, name, quote(name) + " = " + format_number(v) + " is too large for a 32-bit float");
  if (is_time) return v;
  if (!range.contains(v))
    r.fail(n, name, quote(name) + " must be " + range.describe() + ", got " + format_number(v),
           "it is a value of " + target);
  return v;
}

void read_keys(const Reader& r, const toml::table& t, const std::string& path, const Slot& slot,
               AnimationTrack& track) {
  const std::string key = path + ".keys";
  const toml::node* n = t.get("keys");
  const std::string example = track.arity == 1 ? "[[0.0, 1.0], [2.0, 3.0]]" : "[[0.0, 1.0, 2.0, 3.0], [2.0, 1.0, 2.0, 4.0]]";
  if (!n)
    r.fail(Reader::line_of(t), key, "missing required key " + quote(key), "keys = " + example + ": rows of [time, values...]");
  const toml::array* rows = n->as_array();
  if (!rows || rows->empty())
    r.fail(*n, key, quote(key) + " must be a non-empty array of [time, values...] rows", "keys = " + example);
  const std::size_t want = 1 + static_cast<std::size_t>(track.arity);
  for (std::size_t k = 0; k < rows->size(); ++k) {
    const toml::node& row_node = (*rows)[k];
    const std::string row_key = key + "[" + std::to_string(k) + "]";
    const toml::array* row = row_node.as_array();
    if (!row || row->size() != want)
      r.fail(row_node, row_key,
             quote(row_key) + " must be " + std::to_string(want) + " numbers (a time and " +
                 std::to_string(track.arity) + (track.arity == 1 ? " value" : " values") + " for " + track.target + ")" +
                 (row ? ", got " + std::to_string(row->size()) : ""),
             "e.g. " + example.substr(1, example.find(']')));
    const double time = key_number(r, (*row)[0], row_key + "[0]", true, {}, track.target);
    if (!track.times.empty() && time <= track.times.back())
      r.fail(row_node, row_key,
             time == track.times.back() ? quote(row_key) + " repeats time " + format_number(time)
                                        : quote(row_key) + " time " + format_number(time) +
                                              " comes before the previous key's " + format_number(track.times.back()),
             "keys must be sorted by time, each time once");
    track.times.push_back(time);
    for (std::size_t c = 1; c < want; ++c)
      track.values.push_back(
          key_number(r, (*row)[c], row_key + "[" + std::to_string(c) + "]", false, slot.range, track.target));
  }
}

[[noreturn]] void fail_pose(const Scene& s, double time, const std::string& target, std::string what, std::string hint) {
  // Point at the (last) track that moves this object.
  int line = 0;
  std::string key = "animation";
  for (std::size_t i = 0; i < s.animation.size(); ++i)
    if (s.animation[i].target.rfind(target, 0) == 0) {
      line = s.animation[i].line;
      key = "animation[" + std::to_string(i) + "]";
    }
  fail_input("at t=" + format_number(time) + " s " + what, s.file.string(), line, key, std::move(hint));
}

double length_sq(const glm::vec3& v) { return glm::dot(glm::dvec3(v), glm::dvec3(v)); }

// The static loader's camera and light checks, for the pose at `time`.
void check_pose(const Scene& s, double time) {
  const glm::dvec3 view = glm::dvec3(s.camera.target) - glm::dvec3(s.camera.position), up(s.camera.up);
  if (glm::dot(view, view) <= 1e-12)
    fail_pose(s, time, "camera", "camera.target equals camera.position", "the animated camera must look somewhere");
  if (glm::dot(up, up) <= 1e-12) fail_pose(s, time, "camera.up", "camera.up is zero-length", "");
  const glm::dvec3 side = glm::cross(view, up);
  if (glm::dot(side, side) <= 1e-8 * glm::dot(view, view) * glm::dot(up, up))
    fail_pose(s, time, "camera", "camera.up is parallel to the view direction", "animate camera.up as well");
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    if (s.lights[i].kind == LightKind::directional && length_sq(s.lights[i].direction) <= 1e-12)
      fail_pose(s, time, "lights[" + std::to_string(i) + "]", "lights[" + std::to_string(i) + "].direction is zero-length",
                "");
}

}  // namespace

AnimationTrack read_animation_track(const Reader& r, const toml::table& t, const std::string& path, Scene& scene) {
  AnimationTrack track;
  track.line = Reader::line_of(t);
  const std::string tkey = path + ".target";
  std::string target;
  if (!r.read(t, path, "target", target))
    r.fail(track.line, tkey, "missing required key " + quote(tkey), "e.g. target = \"camera.position\"");
  Slot slot;
  if (is_graph_target(target)) {  // a graph node's value (scene/graph_animation.h)
    const GraphSlot g = find_graph_slot(target, scene);
    slot.error = g.error;
    slot.hint = g.hint;
    slot.canonical = target;
    track.graph_values = g.values;
  } else {
    slot = find_slot(target, scene);
  }
  const int tline = Reader::line_of(t, "target");
  if (!slot.error.empty()) r.fail(tline, tkey, slot.error, slot.hint);
  for (std::size_t i = 0; i < scene.animation.size(); ++i)
    if (scene.animation[i].target == slot.canonical)
      r.fail(tline, tkey, quote(slot.canonical) + " is already animated by animation[" + std::to_string(i) + "]",
             "one [[animation]] table per value; put all its keys there");
  track.target = slot.canonical;
  track.arity = track.graph_values.empty() ? slot.arity() : static_cast<int>(track.graph_values.size());
  r.read_enum(t, path, "interpolation", kInterpolations, track.interpolation);
  read_keys(r, t, path, slot, track);
  return track;
}

std::array<double, 3> evaluate(const AnimationTrack& tr, double time) {
  std::array<double, 3> out{};
  const std::size_t n = tr.times.size(), a = static_cast<std::size_t>(tr.arity);
  const auto row = [&](std::size_t k) { return tr.values.data() + k * a; };
  // The last key whose time is <= time; before the first key, hold it.
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(tr.times.begin(), tr.times.end(), time) - tr.times.begin());
  if (hi == 0 || hi == n) {
    const double* v = row(hi == 0 ? 0 : n - 1);
    std::copy(v, v + a, out.begin());
    return out;
  }
  const std::size_t lo = hi - 1;
  double u = (time - tr.times[lo]) / (tr.times[hi] - tr.times[lo]);
  if (tr.interpolation == Interpolation::smooth) u = u * u * (3.0 - 2.0 * u);
  for (std::size_t c = 0; c < a; ++c) out[c] = row(lo)[c] + (row(hi)[c] - row(lo)[c]) * u;
  return out;
}

Scene animated(const Scene& scene, double time) {
  Scene out = scene;
  if (scene.animation.empty()) return out;
  pose_graph_at(out, time);  // the graph rebuilt with its nodes' values at `time`
  for (const AnimationTrack& tr : scene.animation) {
    if (!tr.graph_values.empty()) continue;
    const Slot slot = find_slot(tr.target, out);
    if (!slot.error.empty()) fail_input(slot.error, scene.file.string(), tr.line, "animation");
    const std::array<double, 3> v = evaluate(tr, time);
    if (slot.scalar) *slot.scalar = static_cast<float>(v[0]);
    else *slot.vec = glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
  }
  check_pose(out, time);
  return out;
}

std::string target_value(Scene& scene, const std::string& target, std::array<double, 3>* value, int* arity,
                         bool set) {
  const Slot slot = find_slot(target, scene);
  if (!slot.error.empty()) return slot.error + (slot.hint.empty() ? "" : " (" + slot.hint + ")");
  *arity = slot.arity();
  if (set && slot.scalar) *slot.scalar = static_cast<float>((*value)[0]);
  if (set && slot.vec) *slot.vec = glm::vec3(glm::dvec3((*value)[0], (*value)[1], (*value)[2]));
  if (slot.scalar) *value = {*slot.scalar, 0.0, 0.0};
  else *value = {slot.vec->x, slot.vec->y, slot.vec->z};
  return "";
}

}  // namespace ms
