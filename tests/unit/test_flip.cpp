// LDR-FLIP (io/flip.h), written from the paper, against NVIDIA's own
// implementation: the expected values come from the flip-evaluator 1.7
// package on the same synthetic pairs (tools/flip-reference.py prints them).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "io/compare.h"
#include "io/flip.h"

namespace ms {
namespace {

constexpr int W = 48, H = 32;

float q(double v) { return static_cast<float>(std::round(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0); }

Image make(const std::function<void(int, int, float*)>& f) {
  Image img;
  img.width = W;
  img.height = H;
  img.channels = {"R", "G", "B"};
  img.pixels.resize(W * H * 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) f(x, y, &img.pixels[(y * W + x) * 3]);
  return img;
}

Image gradient() {
  return make([](int x, int y, float* p) {
    p[0] = q(x / double(W - 1));
    p[1] = q(y / double(H - 1));
    p[2] = q(0.5);
  });
}

Image with_block(Image img) {
  for (int y = 10; y < 16; ++y)
    for (int x = 20; x < 26; ++x) {
      float* p = &img.pixels[(y * W + x) * 3];
      p[0] = q(1.0);
      p[1] = q(0.2);
      p[2] = q(0.1);
    }
  return img;
}

Image checker(int shift) {
  return make([shift](int x, int y, float* p) {
    p[0] = p[1] = p[2] = ((x + shift) / 4 + y / 4) % 2 == 0 ? q(0.9) : q(0.1);
  });
}

struct Expected {
  double mean, max, at_22_12, at_0_0;
};

// The reference computes in 32-bit floats (its ppd is 67.020645f), we in
// doubles: values agree to about 1e-5, far under any threshold one would set.
void expect_flip(const Image& a, const Image& b, const Expected& e) {
  const FlipMap f = flip_ldr(a, b);
  EXPECT_NEAR(f.mean, e.mean, 2e-5);
  EXPECT_NEAR(f.max, e.max, 2e-5);
  EXPECT_NEAR(f.error[12 * W + 22], e.at_22_12, 2e-5);
  EXPECT_NEAR(f.error[0], e.at_0_0, 2e-5);
}

TEST(Flip, MatchesTheAuthorsImplementation) {
  EXPECT_NEAR(flip_default_ppd(), 67.0206433, 1e-6);  // 0.7 m * 3840 px / 0.7 m, per degree
  expect_flip(gradient(), with_block(gradient()), {0.0411717035, 0.881161273, 0.881161273, 0.0});
  expect_flip(checker(0), checker(1), {0.287373275, 0.973613739, 0.198953167, 0.0436973423});
  expect_flip(gradient(), checker(0), {0.856431901, 0.991512239, 0.825485528, 0.981791019});
}

TEST(Flip, IsZeroForIdenticalImagesAndAMetricOfCompare) {
  EXPECT_EQ(flip_ldr(checker(0), checker(0)).max, 0.0);
  CompareOptions o;
  o.flip_ppd = flip_default_ppd();
  const CompareMetrics m = compare_images(gradient(), with_block(gradient()), o);
  EXPECT_NEAR(metric_value(m, Metric::flip), 0.0411717035, 2e-5);
  EXPECT_TRUE(within_threshold(m, Metric::flip, 0.05));
  EXPECT_FALSE(within_threshold(m, Metric::flip, 0.04));
  EXPECT_EQ(parse_metric("flip"), Metric::flip);
  // Not asked for: NaN, which never passes a threshold.
  EXPECT_TRUE(std::isnan(compare_images(gradient(), checker(0)).flip_mean));
}

}  // namespace
}  // namespace ms
