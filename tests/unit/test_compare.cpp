// io/compare: the metric functions on small synthetic images whose
// metrics are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/compare.h"
#include "core/error.h"

namespace ms {
namespace {

Image flat(int w, int h, std::vector<std::string> channels, float v = 0.0f) {
  Image img;
  img.width = w;
  img.height = h;
  img.channels = std::move(channels);
  img.pixels.assign(static_cast<size_t>(w) * h * img.channels.size(), v);
  return img;
}

float& px(Image& img, int x, int y, int c) {
  return img.pixels[(static_cast<size_t>(y) * img.width + x) * img.nchannels() + c];
}

// 10x10 RGB black, and a copy with pixel (3,4) green raised by 0.5.
struct OnePixel : ::testing::Test {
  Image a = flat(10, 10, {"R", "G", "B"});
  Image b = a;
  void SetUp() override { px(b, 3, 4, 1) = 0.5f; }
};

TEST_F(OnePixel, MetricsHaveTheirClosedForms) {
  const CompareMetrics m = compare_images(a, b);
  EXPECT_EQ(m.width, 10);
  EXPECT_EQ(m.height, 10);
  EXPECT_EQ(m.channels, 3);
  EXPECT_DOUBLE_EQ(m.max_abs, 0.5);
  EXPECT_EQ(m.max_x, 3);
  EXPECT_EQ(m.max_y, 4);
  EXPECT_EQ(m.max_channel, 1);
  EXPECT_NEAR(m.mean_abs, 0.5 / 300.0, 1e-12);
  EXPECT_EQ(m.pixels, 100);
  EXPECT_EQ(m.pixels_over, 1);
  EXPECT_DOUBLE_EQ(m.fraction_over, 0.01);
  // MSE = 0.25 / 300 over RGB, peak 1: PSNR = 10 log10(1200).
  EXPECT_NEAR(m.psnr, 10.0 * std::log10(1200.0), 1e-9);
  EXPECT_FALSE(m.identical());
}

TEST_F(OnePixel, ThresholdBoundaryPassesAndOneUlpStricterFails) {
  const CompareMetrics m = compare_images(a, b);
  for (Metric metric : {Metric::psnr, Metric::mae, Metric::max, Metric::fraction}) {
    const double v = metric_value(m, metric);
    EXPECT_TRUE(within_threshold(m, metric, v)) << metric_name(metric);
    // Stricter: a higher PSNR demanded, or a lower error allowed.
    const double stricter = metric == Metric::psnr ? std::nextafter(v, 1e9) : std::nextafter(v, -1.0);
    EXPECT_FALSE(within_threshold(m, metric, stricter)) << metric_name(metric);
    EXPECT_FALSE(within_threshold(m, metric, default_threshold(metric))) << metric_name(metric);
  }
  EXPECT_TRUE(within_threshold(m, Metric::psnr, 30.0));
  EXPECT_FALSE(within_threshold(m, Metric::psnr, 31.0));
  EXPECT_TRUE(within_threshold(m, Metric::max, 0.5));
  EXPECT_FALSE(within_threshold(m, Metric::max, 0.49));
}

TEST(Compare, IdenticalImagesHaveInfinitePsnrAndPassTheDefaults) {
  Image a = flat(7, 5, {"R", "G", "B"}, 0.25f);
  px(a, 2, 2, 0) = 0.9f;
  const CompareMetrics m = compare_images(a, a);
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr > 0);
  EXPECT_EQ(m.mean_abs, 0.0);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_EQ(m.pixels_over, 0);
  EXPECT_TRUE(m.identical());
  for (Metric metric : {Metric::psnr, Metric::mae, Metric::max, Metric::fraction})
    EXPECT_TRUE(within_threshold(m, metric, default_threshold(metric))) << metric_name(metric);
}

TEST(Compare, TrailingAlphaIsNotCompared) {
  Image a = flat(4, 4, {"R", "G", "B", "A"}, 1.0f);
  Image b = a;
  px(b, 1, 1, 3) = 0.0f;
  const CompareMetrics m = compare_images(a, b);
  EXPECT_EQ(m.channels, 3);
  EXPECT_TRUE(m.identical());
  px(b, 1, 1, 2) = 0.0f;  // but blue is
  EXPECT_DOUBLE_EQ(compare_images(a, b).max_abs, 1.0);
}

TEST(Compare, NonColourChannelsAreAllCompared) {
  Image a = flat(3, 3, {"Z", "N.x", "N.y", "N.z"});
  Image b = a;
  px(b, 0, 0, 3) = 0.125f;
  const CompareMetrics m = compare_images(a, b);
  EXPECT_EQ(m.channels, 4);
  EXPECT_DOUBLE_EQ(m.max_abs, 0.125);
}

// Neighbouring 8-bit levels (k/255 vs (k+1)/255, as a PNG reads) are within
// the default 1/255 for every k; two levels apart is over it.
TEST(Compare, PixelThresholdOfOneLevelForgivesExactlyOneLevel) {
  Image a = flat(254, 1, {"R", "G", "B"}), b1 = a, b2 = a;
  for (int k = 0; k < 254; ++k)
    for (int c = 0; c < 3; ++c) {
      px(a, k, 0, c) = static_cast<float>(k) / 255.0f;
      px(b1, k, 0, c) = static_cast<float>(k + 1) / 255.0f;
      px(b2, k, 0, c) = static_cast<float>(k + 2) / 255.0f;
    }
  EXPECT_EQ(compare_images(a, b1).pixels_over, 0);
  EXPECT_EQ(compare_images(a, b2).pixels_over, 254);
  CompareOptions tight;
  tight.pixel_threshold = 0.0f;
  EXPECT_EQ(compare_images(a, b1, tight).pixels_over, 254);
  CompareOptions loose;
  loose.pixel_threshold = 2.0f / 255.0f;
  EXPECT_EQ(compare_images(a, b2, loose).pixels_over, 0);
}

TEST(Compare, NonFiniteValuesAlwaysFail) {
  const Image a = flat(4, 4, {"R", "G", "B"});
  Image b = a;
  px(b, 2, 3, 0) = std::numeric_limits<float>::quiet_NaN();
  px(b, 0, 0, 1) = std::numeric_limits<float>::infinity();
  const CompareMetrics m = compare_images(a, b);
  EXPECT_EQ(m.nonfinite_a, 0);
  EXPECT_EQ(m.nonfinite_b, 2);
  EXPECT_FALSE(m.identical());
  for (Metric metric : {Metric::psnr, Metric::mae, Metric::max, Metric::fraction})
    EXPECT_FALSE(within_threshold(m, metric, metric == Metric::psnr ? -1e9 : 1e9)) << metric_name(metric);
}

TEST(Compare, DifferentSizesOrChannelCountsAreBadInput) {
  const Image a = flat(4, 4, {"R", "G", "B"});
  try {
    compare_images(a, flat(4, 5, {"R", "G", "B"}));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_NE(std::string(e.what()).find("4x4 vs 4x5"), std::string::npos) << e.what();
  }
  try {
    compare_images(a, flat(4, 4, {"R", "G", "B", "A"}));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_NE(std::string(e.what()).find("channel count"), std::string::npos) << e.what();
  }
}

TEST(Compare, ParseMetric) {
  EXPECT_EQ(parse_metric("psnr"), Metric::psnr);
  EXPECT_EQ(parse_metric("mae"), Metric::mae);
  EXPECT_EQ(parse_metric("max"), Metric::max);
  EXPECT_EQ(parse_metric("fraction"), Metric::fraction);
  EXPECT_EQ(parse_metric("flip"), Metric::flip);
  for (Metric m : {Metric::psnr, Metric::mae, Metric::max, Metric::fraction, Metric::flip})
    EXPECT_EQ(parse_metric(metric_name(m)), m);
  try {
    parse_metric("ssim");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_NE(std::string(e.what()).find("--metric"), std::string::npos) << e.what();
  }
}

TEST_F(OnePixel, HeatMapIsBrightestWhereTheImagesDiffer) {
  const Image heat = diff_heatmap(a, b);
  EXPECT_EQ(heat.width, 10);
  EXPECT_EQ(heat.height, 10);
  ASSERT_EQ(heat.nchannels(), 3);
  auto luma = [&](int x, int y) { return heat.at(x, y, 0) + heat.at(x, y, 1) + heat.at(x, y, 2); };
  const float hot = luma(3, 4);
  EXPECT_GT(hot, 2.0f);  // inferno's top is a pale yellow
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      if (x != 3 || y != 4) EXPECT_LT(luma(x, y), 0.1f) << x << "," << y;
  // A fixed scale twice the difference puts it mid-map, not at the top.
  EXPECT_LT(diff_heatmap(a, b, 1.0f).at(3, 4, 1), heat.at(3, 4, 1));
}

TEST(Compare, HeatMapPutsNonFiniteDifferencesAtTheTop) {
  const Image a = flat(4, 4, {"R", "G", "B"});
  Image b = a;
  px(b, 1, 1, 0) = 0.25f;
  px(b, 2, 2, 2) = std::numeric_limits<float>::quiet_NaN();
  const Image heat = diff_heatmap(a, b);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(heat.at(2, 2, c), heat.at(1, 1, c)) << c;
  EXPECT_GT(heat.at(2, 2, 1), 0.9f);
}

TEST(Compare, HeatMapOfIdenticalImagesIsBlack) {
  const Image a = flat(5, 3, {"R", "G", "B"}, 0.7f);
  const Image heat = diff_heatmap(a, a);
  for (float v : heat.pixels) EXPECT_LT(v, 0.05f);
}

}  // namespace
}  // namespace ms
