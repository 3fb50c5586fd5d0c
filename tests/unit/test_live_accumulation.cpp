// live/accumulation.h: what each viewer frame adds while nothing changes,
// and what starts it again. The converged image itself is checked against
// render --spp in tests/cli/test_viewer.cpp.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "live/accumulation.h"
#include "render/samples.h"

namespace ms::live {
namespace {

AccumulationKey key() {
  AccumulationKey k;
  k.generation = 1;
  k.width = 160;
  k.height = 90;
  k.params = {1.0f};
  return k;
}

// Draws frames until `n` steps have been taken; returns the ranges drawn.
std::vector<std::pair<int, int>> run(Accumulation& a, const AccumulationKey& k, int target, int n) {
  std::vector<std::pair<int, int>> out;
  for (int i = 0; i < n; ++i) {
    const Accumulation::Step s = a.next(k, false, target);
    if (s.draw) {
      out.emplace_back(s.begin, s.end);
      EXPECT_EQ(s.spp, target);
      a.drawn();
    }
  }
  return out;
}

TEST(LiveAccumulation, AddsOneSampleAFrameUpToTheTargetThenStops) {
  Accumulation a;
  const auto drawn = run(a, key(), 4, 10);
  EXPECT_EQ(drawn, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 3}, {3, 4}}));
  EXPECT_TRUE(a.converged());
  EXPECT_EQ(a.samples(), 4);
}

TEST(LiveAccumulation, AnyChangeStartsAgain) {
  Accumulation a;
  run(a, key(), 4, 3);
  ASSERT_EQ(a.samples(), 3);
  const auto restarts = [&](AccumulationKey k, bool scene_changed = false) {
    Accumulation b;
    run(b, key(), 4, 3);
    const Accumulation::Step s = b.next(k, scene_changed, 4);
    return s.draw && s.begin == 0 && s.end == 1;
  };
  AccumulationKey k = key();
  EXPECT_FALSE(restarts(k));  // nothing changed: sample 3 next
  k.camera.position.x += 0.01f;
  EXPECT_TRUE(restarts(k));
  k = key();
  k.time = 0.5;
  EXPECT_TRUE(restarts(k));
  k = key();
  k.params = {1.5f};
  EXPECT_TRUE(restarts(k));
  k = key();
  ++k.generation;
  EXPECT_TRUE(restarts(k));
  k = key();
  k.width = 320;
  EXPECT_TRUE(restarts(k));
  k = key();
  k.debug_view = 2;
  EXPECT_TRUE(restarts(k));
  EXPECT_TRUE(restarts(key(), true));  // a panel value
}

TEST(LiveAccumulation, TargetOneIsOffAndNoLimitNeverStops) {
  Accumulation off;
  for (int i = 0; i < 3; ++i) {
    const Accumulation::Step s = off.next(key(), false, 1);
    EXPECT_TRUE(s.draw);
    EXPECT_EQ(s.begin, 0);
    EXPECT_EQ(s.end, 1);
    EXPECT_EQ(s.spp, 1);
    off.drawn();
  }
  EXPECT_FALSE(off.converged());
  Accumulation open;
  for (int i = 0; i < 300; ++i) {
    const Accumulation::Step s = open.next(key(), false, Accumulation::kNoLimit);
    ASSERT_TRUE(s.draw);
    EXPECT_TRUE(s.open_ended);
    EXPECT_EQ(s.begin, i);
    open.drawn();
  }
  EXPECT_FALSE(open.converged());
  EXPECT_EQ(open.samples(), 300);
}

TEST(LiveAccumulation, OpenSamplesAreDistinctInThePixelAndPrefixStable) {
  const std::vector<glm::vec2> all = open_samples(0, 256);
  ASSERT_EQ(all.size(), 256u);
  EXPECT_EQ(all[0], glm::vec2(0.5f));  // one sample: the pixel centre
  std::set<std::pair<float, float>> seen;
  int quadrant[4] = {0, 0, 0, 0};
  for (const glm::vec2& s : all) {
    EXPECT_GE(s.x, 0.0f);
    EXPECT_LT(s.x, 1.0f);
    EXPECT_GE(s.y, 0.0f);
    EXPECT_LT(s.y, 1.0f);
    seen.insert({s.x, s.y});
    ++quadrant[(s.x >= 0.5f) + 2 * (s.y >= 0.5f)];
  }
  EXPECT_EQ(seen.size(), all.size());
  for (int q : quadrant) EXPECT_NEAR(q, 64, 8);  // low discrepancy: each quarter gets its share
  EXPECT_EQ(open_samples(100, 102), std::vector<glm::vec2>(all.begin() + 100, all.begin() + 102));
}

}  // namespace
}  // namespace ms::live
