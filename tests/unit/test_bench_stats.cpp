// bench/stats (nearest-rank percentiles), bench's cost summary of an AOV
// image, and render/aov's channel bookkeeping and heat-map mirror.
#include <gtest/gtest.h>

#include "bench/bench.h"
#include "bench/stats.h"
#include "core/error.h"
#include "render/aov.h"

namespace ms {
namespace {

TEST(BenchStats, NearestRankPercentilesAreMeasuredValues) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);  // 1..20, unsorted
  const Summary s = summarize(v);
  EXPECT_EQ(s.min, 1);
  EXPECT_EQ(s.max, 20);
  EXPECT_EQ(s.median, 10.5);  // even count: mean of the middle two
  EXPECT_EQ(s.p95, 19);       // rank ceil(0.95 * 20) = 19
  EXPECT_DOUBLE_EQ(s.mean, 10.5);
  EXPECT_EQ(summarize({3, 1, 2}).median, 2);
  EXPECT_EQ(summarize({5}).p95, 5);
  EXPECT_EQ(summarize({}).max, 0);
  // With fewer than 20 values p95 is the maximum.
  EXPECT_EQ(summarize({1, 2, 3, 4, 100}).p95, 100);
}

TEST(BenchStats, CountStatsP99) {
  std::vector<double> v(1000, 10.0);
  v[0] = 500;  // one outlier in a thousand: above p99
  for (int i = 1; i <= 9; ++i) v[i] = 50;  // nine at 50: ranks 1..990 are 10, 991..999 are 50
  const CountStats c = count_stats(v);
  EXPECT_EQ(c.max, 500);
  EXPECT_EQ(c.p99, 10);
  v[10] = 50;  // one more at 50 and rank 990 is one of them
  EXPECT_EQ(count_stats(v).p99, 50);
  EXPECT_NEAR(c.mean, (990 * 10 + 9 * 50 + 500) / 1000.0, 1e-12);
}

Image aov_image(int w, int h) {
  Image img;
  img.width = w;
  img.height = h;
  img.channels = kAovChannels;
  img.pixels.assign(static_cast<size_t>(w) * h * kAovChannels.size(), 0.0f);
  return img;
}

void set(Image& img, int p, const std::string& name, float v) {
  const auto c = std::find(img.channels.begin(), img.channels.end(), name) - img.channels.begin();
  img.pixels[p * img.channels.size() + c] = v;
}

TEST(BenchCost, FractionsAreOverAllPixels) {
  Image img = aov_image(4, 1);
  for (int p = 0; p < 4; ++p) set(img, p, "steps", static_cast<float>(10 * (p + 1)));
  set(img, 0, "hit", 1);
  set(img, 1, "hit", 1);
  set(img, 1, "step_cap", 1);
  set(img, 2, "sdf_evals", 8);
  const BenchCost c = measure_cost(img);
  EXPECT_EQ(c.pixels, 4);
  EXPECT_DOUBLE_EQ(c.primary_steps.mean, 25.0);
  EXPECT_EQ(c.primary_steps.max, 40);
  EXPECT_DOUBLE_EQ(c.hit_fraction, 0.5);
  EXPECT_DOUBLE_EQ(c.step_cap_fraction, 0.25);
  EXPECT_DOUBLE_EQ(c.sdf_evals.mean, 2.0);
}

TEST(AovChannels, CanonicalOrderWithHitFirst) {
  EXPECT_EQ(aov_channels({"normal", "depth"}), (std::vector<std::string>{"hit", "Z", "N.x", "N.y", "N.z"}));
  EXPECT_EQ(aov_channels({"cost", "steps", "cost"}),
            (std::vector<std::string>{"hit", "steps", "shadow_steps", "reflection_steps", "sdf_evals", "step_cap"}));
  std::vector<std::string> everything(kAovNames.begin(), kAovNames.end());
  EXPECT_EQ(aov_channels(everything), kAovChannels);
  try {
    aov_channels({"depth", "normals"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_EQ(e.info().key, "--aov");
    EXPECT_NE(std::string(e.what()).find("normals"), std::string::npos);
  }
}

TEST(AovChannels, SelectAndAppend) {
  Image a;
  a.width = 2;
  a.height = 1;
  a.channels = {"R", "G"};
  a.pixels = {1, 2, 3, 4};
  Image b = a;
  b.channels = {"Z", "hit"};
  b.pixels = {5, 6, 7, 8};
  const Image ab = append_channels(a, b);
  EXPECT_EQ(ab.channels, (std::vector<std::string>{"R", "G", "Z", "hit"}));
  EXPECT_EQ(ab.pixels, (std::vector<float>{1, 2, 5, 6, 3, 4, 7, 8}));
  const Image s = select_channels(ab, {"hit", "R"});
  EXPECT_EQ(s.pixels, (std::vector<float>{6, 1, 8, 3}));
  EXPECT_THROW(select_channels(ab, {"B"}), std::out_of_range);
}

TEST(AovHeat, LogScaleAndRampStops) {
  EXPECT_FLOAT_EQ(steps_heat_position(0), 0.0f);
  EXPECT_FLOAT_EQ(steps_heat_position(3), 0.25f);
  EXPECT_FLOAT_EQ(steps_heat_position(15), 0.5f);
  EXPECT_FLOAT_EQ(steps_heat_position(255), 1.0f);
  EXPECT_FLOAT_EQ(steps_heat_position(4000), 1.0f);
  EXPECT_EQ(heat_ramp(0.0f), glm::vec3(0.0f, 0.0f, 0.25f));
  EXPECT_EQ(heat_ramp(1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(heat_ramp(0.75f), glm::vec3(1.0f, 0.9f, 0.0f));
}

}  // namespace
}  // namespace ms
