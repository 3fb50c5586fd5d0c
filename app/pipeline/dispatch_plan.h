// --dispatch auto's measuring plan, without the GL: which frame
// sizes and work groups the probe times, and what it picks. The caller
// gives the timer (pipeline/dispatch_probe.h draws the job's scene with it), so
// the plan is tested with made-up timings (tests/unit/test_dispatch_plan.cpp).
//
//   - Size: from kProbeWidth x kProbeHeight each side doubles (the last step
//     to kProbeMaxWidth x kProbeMaxHeight) while the faster of the two
//     dispatches takes under kProbeMinMs a frame: a shorter frame measures
//     the launch, not the device (a datacenter GPU draws 256x144 in
//     microseconds). llvmpipe stays at the first size.
//   - Groups: when compute wins at 8x8 and no group was given, it is timed
//     at each of kProbeGroups' others at that size; the fastest is kept.
//     A given group is the only one timed.
//
//   const DispatchProbe p = plan_dispatch(given_group, [&](Dispatch d, ComputeGroup g, int w, int h) {
//     return median_frame_ms(d, g, w, h);
//   });
//   p.choice;           // fragment, or compute with its group
//   describe_probe(p);  // "fragment 12.10 ms, compute 9.80 ms (8x8) a frame at 256x144"
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/compute_frame.h"

namespace ms {

constexpr int kProbeWidth = 256, kProbeHeight = 144, kProbeFrames = 3;
constexpr int kProbeMaxWidth = 1920, kProbeMaxHeight = 1080;
constexpr double kProbeMinMs = 2.0;
// The work-group shapes it tries; the first is the default.
inline const ComputeGroup kProbeGroups[] = {{8, 8, 0}, {16, 8, 0}, {16, 16, 0}, {32, 4, 0}};

// Median wall milliseconds of one frame drawn by d (with g when compute) at w x h.
using ProbeTimer = std::function<double(Dispatch d, ComputeGroup g, int w, int h)>;

struct DispatchProbe {
  DispatchChoice choice;
  int width = 0, height = 0;  // the size the choice was made at
  double fragment_ms = 0.0;
  struct Timed {
    ComputeGroup group;
    double ms = 0.0;
  };
  std::vector<Timed> compute;  // in the order timed: the first is `given` (or 8x8)
};

// The size after a frame at w x h whose faster dispatch took `ms`, or none
// when that frame was long enough or the largest.
std::optional<std::pair<int, int>> next_probe_size(int w, int h, double ms);

DispatchProbe plan_dispatch(std::optional<ComputeGroup> given, const ProbeTimer& time);

// The probe's figures for -v: "fragment 12.10 ms, compute 9.80 ms (8x8), 9.10 (16x8) a frame at 1024x576".
std::string describe_probe(const DispatchProbe& p);

}  // namespace ms
