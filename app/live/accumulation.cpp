#include "live/accumulation.h"

namespace ms::live {

bool same_key(const AccumulationKey& a, const AccumulationKey& b) {
  return a.generation == b.generation && a.debug_view == b.debug_view && a.width == b.width && a.height == b.height &&
         a.camera.position == b.camera.position && a.camera.target == b.camera.target && a.camera.up == b.camera.up &&
         a.camera.fov_deg == b.camera.fov_deg && a.time == b.time && a.params == b.params;
}

Accumulation::Step Accumulation::next(const AccumulationKey& key, bool scene_changed, int target) {
  if (target < 0) target = 1;
  if (!same_key(key, key_) || scene_changed || target != target_) samples_ = 0;
  key_ = key;
  target_ = target;
  Step s;
  if (target == 1) {  // off: one fresh sample a frame
    pending_end_ = 0;
    return s;
  }
  s.open_ended = target == kNoLimit;
  s.spp = s.open_ended ? 1 : target;
  if (!s.open_ended && samples_ >= target) {
    s.draw = false;
    pending_end_ = samples_;
    return s;
  }
  s.begin = samples_;
  s.end = samples_ + 1;
  pending_end_ = s.end;
  return s;
}

}  // namespace ms::live
