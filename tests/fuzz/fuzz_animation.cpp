// The keyframe parser: the input is appended to a fixed valid scene (a
// camera, a point and a directional light, two materials), so nearly every
// byte lands in [[animation]] tables. A scene that loads is then evaluated
// at several times: every value must be finite and stay within its track's
// key values (linear and smooth blends never overshoot), and animated()
// may only fail with ms::Error.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "fuzz_util.h"
#include "scene/animation.h"
#include "scene/load.h"

namespace {

constexpr const char* kHeader = R"([scene]
map = "map.glsl"
[camera]
position = [0.0, 1.0, 4.0]
target = [0.0, 0.5, 0.0]
[[lights]]
type = "point"
position = [2.0, 4.0, 3.0]
[[lights]]
type = "directional"
direction = [-1.0, -1.0, 0.0]
[[materials]]
name = "floor"
[[materials]]
name = "ball"
color = [0.9, 0.1, 0.1]
)";

void check_track(const ms::AnimationTrack& tr, double t) {
  const std::array<double, 3> v = ms::evaluate(tr, t);
  const size_t a = static_cast<size_t>(tr.arity);
  for (size_t c = 0; c < a; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < tr.times.size(); ++k) {
      lo = std::min(lo, tr.values[k * a + c]);
      hi = std::max(hi, tr.values[k * a + c]);
    }
    const double slack = 1e-9 * std::max(1.0, std::max(std::abs(lo), std::abs(hi)));
    if (!std::isfinite(v[c]) || v[c] < lo - slack || v[c] > hi + slack)
      ms::fuzz::violated("an animated value left its keys' range", tr.target);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ms;
  fuzz::Workspace& ws = fuzz::workspace();
  static const bool ready = [&] {
    fuzz::put(ws.scene() / "map.glsl", "vec2 map(vec3 p) { return vec2(length(p) - 1.0, 0.0); }\n");
    return true;
  }();
  (void)ready;
  std::string text = kHeader;
  text.append(reinterpret_cast<const char*>(data), size);
  Scene scene;
  try {
    scene = parse_scene(text, ws.scene() / "anim.toml");
  } catch (const Error&) {
    return 0;
  }
  // Times around and between the keys, and far outside them.
  std::vector<double> times = {-1e300, -1.0, 0.0, 0.5, 1.0, 3.25, 1e300};
  for (const AnimationTrack& tr : scene.animation)
    for (size_t k = 0; k < tr.times.size(); ++k) {
      times.push_back(tr.times[k]);
      if (k + 1 < tr.times.size()) times.push_back(tr.times[k] + 0.5 * (tr.times[k + 1] - tr.times[k]));
    }
  for (double t : times) {
    for (const AnimationTrack& tr : scene.animation) check_track(tr, t);
    try {
      animated(scene, t);
    } catch (const Error&) {
    }
  }
  return 0;
}
