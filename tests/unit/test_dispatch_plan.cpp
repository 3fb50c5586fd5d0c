// pipeline/dispatch_plan.h: --dispatch auto's sizes and groups, with made-up
// timings (the GL side is tests/cli/test_dispatch_paths.cpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipeline/dispatch_plan.h"

namespace ms {
namespace {

struct Call {
  Dispatch d;
  std::string group;
  int w, h;
};

// A device whose frame costs `ns_per_pixel` (fragment) or that times
// `compute_factor` (compute), plus `launch_ms` each; 16x8 is `g16x8` as fast
// again as the other groups.
struct FakeDevice {
  double ns_per_pixel = 0, compute_factor = 1, launch_ms = 0, g16x8 = 1;
  std::vector<Call> calls;
  ProbeTimer timer() {
    return [this](Dispatch d, ComputeGroup g, int w, int h) {
      calls.push_back({d, d == Dispatch::compute ? group_name(g) : "", w, h});
      double ms = launch_ms + ns_per_pixel * w * h * 1e-6;
      if (d == Dispatch::compute) ms *= compute_factor * (g.x == 16 && g.y == 8 ? g16x8 : 1.0);
      return ms;
    };
  }
};

TEST(DispatchPlan, ASlowDeviceIsProbedAtTheFirstSizeOnly) {
  FakeDevice dev{500};  // llvmpipe-like: 256x144 takes 18 ms
  const DispatchProbe p = plan_dispatch(std::nullopt, dev.timer());
  EXPECT_EQ(p.width, kProbeWidth);
  EXPECT_EQ(p.height, kProbeHeight);
  ASSERT_EQ(dev.calls.size(), 2u) << "fragment and compute 8x8, once each";
  EXPECT_EQ(p.choice.dispatch, Dispatch::fragment) << "equal times: fragment (no reason to change)";
}

TEST(DispatchPlan, AFastDeviceGrowsTheFrameUntilItMeasures) {
  FakeDevice dev{1, 0.5};  // 256x144 in 0.04 ms: launch-bound, meaningless
  const DispatchProbe p = plan_dispatch(std::nullopt, dev.timer());
  EXPECT_EQ(p.width, kProbeMaxWidth);
  EXPECT_EQ(p.height, kProbeMaxHeight);
  std::vector<std::pair<int, int>> sizes;
  for (const Call& c : dev.calls)
    if (c.d == Dispatch::fragment) sizes.push_back({c.w, c.h});
  const std::vector<std::pair<int, int>> want = {{256, 144}, {512, 288}, {1024, 576}, {1920, 1080}};
  EXPECT_EQ(sizes, want);
}

TEST(DispatchPlan, GrowingStopsOnceAFrameTakesLongEnough) {
  // 512x288 at 20 ns a pixel: 2.9 ms on the faster (fragment), past kProbeMinMs.
  FakeDevice dev{20, 1.5};
  const DispatchProbe p = plan_dispatch(std::nullopt, dev.timer());
  EXPECT_EQ(p.width, 512);
  EXPECT_EQ(p.height, 288);
  EXPECT_EQ(p.choice.dispatch, Dispatch::fragment);
  EXPECT_EQ(p.compute.size(), 1u) << "fragment won: compute's other groups are not timed";
}

TEST(DispatchPlan, ComputesWinnerIsTimedAtEveryGroupAndTheFastestKept) {
  FakeDevice dev{500, 0.5, 0, 0.8};
  const DispatchProbe p = plan_dispatch(std::nullopt, dev.timer());
  ASSERT_EQ(p.compute.size(), std::size(kProbeGroups));
  std::vector<std::string> groups;
  for (const DispatchProbe::Timed& t : p.compute) groups.push_back(group_name(t.group));
  EXPECT_EQ(groups, (std::vector<std::string>{"8x8", "16x8", "16x16", "32x4"}));
  EXPECT_EQ(p.choice.dispatch, Dispatch::compute);
  EXPECT_EQ(group_name(p.choice.group), "16x8");
  for (const Call& c : dev.calls) EXPECT_EQ(c.w, kProbeWidth) << "the groups are timed at the chosen size";
}

TEST(DispatchPlan, AGivenGroupIsTheOnlyOneTimed) {
  FakeDevice dev{500, 0.5, 0, 0.8};
  const DispatchProbe p = plan_dispatch(ComputeGroup{32, 4, 0}, dev.timer());
  ASSERT_EQ(p.compute.size(), 1u);
  EXPECT_EQ(p.choice.dispatch, Dispatch::compute);
  EXPECT_EQ(group_name(p.choice.group), "32x4");
  for (const Call& c : dev.calls)
    if (c.d == Dispatch::compute) EXPECT_EQ(c.group, "32x4");
}

TEST(DispatchPlan, OnlyAWinningComputeIsTimedAtItsOtherGroups) {
  // Compute at 8x8 loses; 16x8 would win, but only a winner's groups are timed.
  FakeDevice dev{500, 1.1, 0, 0.5};
  const DispatchProbe p = plan_dispatch(std::nullopt, dev.timer());
  EXPECT_EQ(p.choice.dispatch, Dispatch::fragment);
  EXPECT_EQ(p.compute.size(), 1u);
}

TEST(DispatchPlan, DescribeNamesEveryTimeAndTheSize) {
  FakeDevice dev{500, 0.5, 0, 0.8};
  const std::string d = describe_probe(plan_dispatch(std::nullopt, dev.timer()));
  EXPECT_EQ(d, "fragment 18.43 ms, compute 9.22 ms (8x8), 7.37 (16x8), 9.22 (16x16), 9.22 (32x4) a frame at 256x144");
}

TEST(DispatchPlan, NextSizeDoublesAndStopsAtTheLargest) {
  EXPECT_EQ(next_probe_size(256, 144, 0.1), std::make_pair(512, 288));
  EXPECT_EQ(next_probe_size(1024, 576, 0.1), std::make_pair(1920, 1080));
  EXPECT_FALSE(next_probe_size(1920, 1080, 0.1));
  EXPECT_FALSE(next_probe_size(256, 144, kProbeMinMs));
}

}  // namespace
}  // namespace ms
