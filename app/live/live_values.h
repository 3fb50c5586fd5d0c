// Fold what the user is not dragging (docs/viewer.md#folding): the viewer
// compiles lights, materials and sky folded into constants, as `render`
// does; a panel drag of one of them rebuilds with that value live (its own
// uniform, the rest still folded) until the drag ends, then it is folded
// again at the final value.
//
//   LiveValues live;
//   live.built(scene, {});                          // at each build
//   if (auto next = live.rebuild(scene, dragging))  // each frame
//     { opts.live = *next; live.built(scene, *next); /* rebuild */ }
//
// ScriptedDrag is --drag's drag for tests: frames A..B move one value, a
// light, material or sky value or one of the scene's ranged uniforms.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shader/scene_params.h"

namespace ms::live {

class LiveValues {
 public:
  // A build assembled from `scene` with `live` kept as uniforms.
  void built(const Scene& scene, std::vector<std::string> live);
  // The live set the next build needs, or nothing when the program shows
  // `now` as it is: while dragging, what it holds plus what changed since
  // the build (folded values that now differ); else none, once anything
  // is live or changed.
  std::optional<std::vector<std::string>> rebuild(const Scene& now, bool dragging) const;
  const std::vector<std::string>& live() const { return live_; }

 private:
  bool any_ = false;
  Scene scene_;
  std::vector<std::string> live_;
};

// "a,b" or "none": for log lines.
std::string live_names(const std::vector<std::string>& live);
// What an assembled scene shader reads from uniforms, comma-separated, or
// "none": its whole tables ("lights", "materials", "sky": *_UNIFORMS 1),
// then the single live values of folded ones ("materials[1].color").
std::string uniform_tables(const std::string& shader_text);

// Whether the viewer draws render's one-pass frame (FrameParams::fused_post,
// shader/assemble.h fused_post_defines()): one sample a frame with no
// accumulation (`accumulate`: ViewState's target, -1 the scene's spp, 0 no
// limit; and the scene's spp 1, which screenshots use), no bloom, no debug
// view, not a Shadertoy shader. Otherwise the accumulating pass and post.
bool fuse_frame(const Scene& scene, int accumulate, int debug_view, bool shadertoy);

struct ScriptedDrag {
  std::string target;         // an animation target: "materials[0].color"; or a uniform's name
  bool uniform = false;       // target names a ranged uniform (the panel's "Scene parameters")
  std::array<double, 3> to{};  // where the drag ends
  long first = -1, last = -1;  // frames; first < 0: no drag
  // At `frame`: moves the value linearly from where it was at `first` to
  // `to` at `last`; returns whether the drag is on (first..last).
  bool apply(Scene& scene, std::vector<SceneParam>& params, long frame);

 private:
  std::array<double, 3> from_{};
};

}  // namespace ms::live
