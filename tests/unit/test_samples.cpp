#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "render/samples.h"

namespace ms {

TEST(Samples, OneSampleIsThePixelCentre) {
  auto s = stratified_samples(1);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_FLOAT_EQ(s[0].x, 0.5f);
  EXPECT_FLOAT_EQ(s[0].y, 0.5f);
}

TEST(Samples, SquareCountsCoverEveryStratumOnce) {
  for (int k : {2, 3, 4, 8}) {
    auto s = stratified_samples(k * k);
    ASSERT_EQ(static_cast<int>(s.size()), k * k);
    std::set<std::pair<int, int>> strata;
    for (auto p : s) {
      ASSERT_GE(p.x, 0.0f);
      ASSERT_LT(p.x, 1.0f);
      ASSERT_GE(p.y, 0.0f);
      ASSERT_LT(p.y, 1.0f);
      strata.insert({static_cast<int>(p.x * k), static_cast<int>(p.y * k)});
    }
    EXPECT_EQ(static_cast<int>(strata.size()), k * k) << "k=" << k;
  }
}

TEST(Samples, NonSquareCountsUseDistinctStrata) {
  auto s = stratified_samples(5);  // 3x3 grid, 5 strata
  ASSERT_EQ(s.size(), 5u);
  std::set<std::pair<int, int>> strata;
  for (auto p : s) strata.insert({static_cast<int>(p.x * 3), static_cast<int>(p.y * 3)});
  EXPECT_EQ(strata.size(), 5u);
}

TEST(Samples, Deterministic) {
  auto a = stratified_samples(16), b = stratified_samples(16);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]);
}

}  // namespace ms
