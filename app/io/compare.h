// Image comparison metrics for `marchstudio compare` and `test`. Pure:
// images in, numbers out; no files, no printing. All arithmetic over pixels
// is OpenImageIO's ImageBufAlgo (compare, absdiff, minchan,
// computePixelStats, color_map, in the image module io/oiio/compare.cpp),
// not loops of our own, except LDR-FLIP, which OpenImageIO lacks (io/flip.h).
#pragma once
#include <cstdint>
#include <limits>
#include <string>


#include "io/image.h"

namespace ms {

// Which metric a threshold applies to.
enum class Metric { psnr, mae, max, fraction, flip };

// "psnr" | "mae" | "max" | "fraction" | "flip"; throws bad_input (key --metric) otherwise.
Metric parse_metric(const std::string& name);
const char* metric_name(Metric m);

struct CompareOptions {
  // A pixel counts as "different" when its largest channel difference
  // exceeds this. 1/255 lets through the one-level rounding differences that
  // two GL drivers produce in 8-bit output, and counts anything larger.
  float pixel_threshold = 1.0f / 255.0f;
  // Also compute LDR-FLIP (io/flip.h) at this many pixels per degree
  // (0: not computed; its figures stay NaN). Image overload only.
  double flip_ppd = 0.0;
};

struct CompareMetrics {
  int width = 0, height = 0;
  int channels = 0;         // channels compared: all but a trailing alpha (RGB for renders)
  // PSNR in dB with a peak of 1.0: 8-bit files are read as [0,1], float
  // files (EXR) are taken as they are, so HDR values above 1 can make it
  // negative. +infinity when the images are identical.
  double psnr = 0.0;
  double mean_abs = 0.0;    // mean over every compared value (pixels x channels)
  double max_abs = 0.0;     // largest single-channel difference
  int max_x = 0, max_y = 0, max_channel = 0;  // where max_abs is (top row 0)
  std::int64_t pixels = 0;
  std::int64_t pixels_over = 0;  // pixels with any channel difference > pixel_threshold
  double fraction_over = 0.0;    // pixels_over / pixels
  float pixel_threshold = 0.0f;  // as used
  // NaN/Inf values in the compared channels of A and B. Any makes the
  // comparison fail whatever the threshold: a NaN would slip through every "<".
  std::int64_t nonfinite_a = 0, nonfinite_b = 0;
  // Mean and largest per-pixel LDR-FLIP, in [0, 1]; NaN when not computed.
  double flip_mean = std::numeric_limits<double>::quiet_NaN();
  double flip_max = std::numeric_limits<double>::quiet_NaN();

  bool identical() const { return max_abs == 0.0 && nonfinite_a == 0 && nonfinite_b == 0; }
};

// Compare A (reference) and B. Throws bad_input when they differ in size or
// channel count (the message names neither file: callers add that).
CompareMetrics compare_images(const Image& a, const Image& b, const CompareOptions& opts = {});

// The metric's value (psnr in dB, the others as fractions of 1).
double metric_value(const CompareMetrics& m, Metric metric);

// The default threshold when none is given: an exact match (PSNR +inf, the
// others 0), so a forgotten --threshold never lets a change through.
double default_threshold(Metric metric);

// Within the threshold? For psnr: PSNR >= threshold. For mae, max,
// fraction, flip: value <= threshold. The boundary value itself passes. False whenever
// either image had non-finite values.
bool within_threshold(const CompareMetrics& m, Metric metric, double threshold);

// A heat map of |A - B|: per pixel the largest channel difference, scaled so
// that `scale` maps to the top of the "inferno" colour map (black = equal,
// yellow-white = scale or more; NaN/Inf differences are at the top too).
// scale <= 0 means the largest difference in the image, so even one-level
// changes show. RGB float, sRGB-encoded display values (for EXR too: it is a
// picture to look at, not data).
Image diff_heatmap(const Image& a, const Image& b, float scale = 0.0f);


}  // namespace ms
