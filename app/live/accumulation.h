// Progressive accumulation in the viewer, as Fragmentarium's subframes:
// while nothing that feeds the image changes, each window frame adds one
// more jittered sample to the frame's float buffer, up to a target (the
// scene's spp, `view --accumulate N`) or without limit; any change starts
// again from one sample. With a target of N the samples are exactly
// `render --spp N`'s (stratified_samples(N), added in the same order), so
// the converged frame equals that render. No GL here: FrameDrawer turns a
// Step into FrameParams (render/frame.h) and says when it was drawn.
//
//   Accumulation acc;
//   const Accumulation::Step s = acc.next(key, scene_changed, target);
//   if (s.draw) { fp.spp = s.spp; fp.sample_begin = s.begin; ...; draw; acc.drawn(); }
#pragma once
#include <vector>

#include "scene/scene.h"

namespace ms::live {

// Everything besides the scene's panel values that the image depends on.
struct AccumulationKey {
  int generation = -1;    // the program (a reload or rebuild makes a new one)
  int debug_view = 0;
  int width = 0, height = 0;  // the render size
  Camera camera;
  double time = 0.0;      // 0 when the image does not depend on time
  std::vector<float> params;  // the scene parameters' values, in order
};
bool same_key(const AccumulationKey& a, const AccumulationKey& b);

class Accumulation {
 public:
  static constexpr int kNoLimit = 0;  // a target: accumulate for as long as nothing changes

  struct Step {
    bool draw = true;       // false: converged, the buffer already holds the frame
    int begin = 0, end = 1; // samples to add: [begin, end)
    int spp = 1;            // the sequence's length (stratified_samples(spp)); no limit: open-ended
    bool open_ended = false;
  };

  // This frame's work. `target` 1 is no accumulation: every frame draws its
  // one sample afresh. `scene_changed`: a panel value differs from the last
  // frame's (lights, materials, sky, exposure).
  Step next(const AccumulationKey& key, bool scene_changed, int target);
  void drawn() { samples_ = pending_end_; }  // the step was drawn
  void restart() { samples_ = 0; }

  int samples() const { return samples_; }  // in the buffer now
  int target() const { return target_; }
  bool converged() const { return target_ != kNoLimit && target_ > 1 && samples_ >= target_; }

 private:
  AccumulationKey key_;
  int samples_ = 0, target_ = 1, pending_end_ = 0;
};

}  // namespace ms::live
