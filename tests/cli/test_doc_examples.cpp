// The docs' flagship Shadertoy example shows its feature: feedback.json's
// moving dot leaves a fading trail (a buffer reading its own last frame), so
// a frame is far from uniform, most of what is lit is trail rather than the
// dot itself, and the picture moves with time.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

struct Stats {
  double stddev = 0;  // of the luminance over all pixels, 0..1
  int lit = 0;        // pixels clearly above the dark ground
};

Stats stats(const Image& img) {
  double sum = 0, sum2 = 0;
  Stats s;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double l = (img.at(x, y, 0) + img.at(x, y, 1) + img.at(x, y, 2)) / 3.0;
      sum += l;
      sum2 += l * l;
      if (l > 0.2) ++s.lit;
    }
  const double n = double(img.width) * img.height, mean = sum / n;
  s.stddev = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  return s;
}

double mean_abs_diff(const Image& a, const Image& b) {
  double d = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) d += std::abs(a.pixels[i] - b.pixels[i]);
  return d / a.pixels.size();
}

TEST(DocExamples, FeedbackJsonDrawsATrail) {
  TempDir dir;
  const std::string json = (source_dir() / "docs" / "examples" / "shadertoy" / "feedback.json").string();
  Image frames[2];
  const char* times[2] = {"1.5", "3"};
  for (int i = 0; i < 2; ++i) {
    const std::string out = (dir / ("f" + std::to_string(i) + ".png")).string();
    const RunResult r = run_marchstudio({"render", json, "--time", times[i], "--size", "128x72", "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    frames[i] = read_image(out);
    ASSERT_EQ(frames[i].width, 128);
  }
  // The dot alone covers about pi * (0.035 * 72)^2 = 20 pixels.
  for (int i = 0; i < 2; ++i) {
    const Stats s = stats(frames[i]);
    EXPECT_GT(s.stddev, 0.05) << "near-uniform frame at time " << times[i];
    EXPECT_GT(s.lit, 100) << "no trail behind the dot at time " << times[i];
    EXPECT_LT(s.lit, 128 * 72 / 2) << "not a dark ground with a trail at time " << times[i];
  }
  EXPECT_GT(mean_abs_diff(frames[0], frames[1]), 0.01) << "the frame does not move with time";
}

}  // namespace
}  // namespace ms::test
