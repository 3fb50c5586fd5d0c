#include "io/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/flip.h"
#include "core/error.h"
#include "io/image_backend.h"

namespace ms {
Metric parse_metric(const std::string& name) {
  if (name == "psnr") return Metric::psnr;
  if (name == "mae") return Metric::mae;
  if (name == "max") return Metric::max;
  if (name == "fraction") return Metric::fraction;
  if (name == "flip") return Metric::flip;
  fail_input("unknown metric '" + name + "'", {}, 0, "--metric", "use psnr, mae, max, fraction or flip");
}

const char* metric_name(Metric m) {
  switch (m) {
    case Metric::psnr: return "psnr";
    case Metric::mae: return "mae";
    case Metric::max: return "max";
    case Metric::fraction: return "fraction";
    case Metric::flip: return "flip";
  }
  return "?";
}

CompareMetrics compare_images(const Image& a, const Image& b, const CompareOptions& opts) {
  CompareMetrics m = image_backend().compare(a, b, opts);
  if (opts.flip_ppd > 0.0 && m.nonfinite_a + m.nonfinite_b == 0) {
    if (a.nchannels() < 3) fail_input("flip needs RGB images, not " + std::to_string(a.nchannels()) + " channels");
    const FlipMap f = flip_ldr(a, b, opts.flip_ppd);
    m.flip_mean = f.mean;
    m.flip_max = f.max;
  }
  return m;
}

double metric_value(const CompareMetrics& m, Metric metric) {
  switch (metric) {
    case Metric::psnr: return m.psnr;
    case Metric::mae: return m.mean_abs;
    case Metric::max: return m.max_abs;
    case Metric::fraction: return m.fraction_over;
    case Metric::flip: return m.flip_mean;
  }
  return 0.0;
}

double default_threshold(Metric metric) {
  return metric == Metric::psnr ? std::numeric_limits<double>::infinity() : 0.0;
}

bool within_threshold(const CompareMetrics& m, Metric metric, double threshold) {
  if (m.nonfinite_a > 0 || m.nonfinite_b > 0) return false;
  const double v = metric_value(m, metric);
  if (std::isnan(v)) return false;
  return metric == Metric::psnr ? v >= threshold : v <= threshold;
}

Image diff_heatmap(const Image& a, const Image& b, float scale) { return image_backend().diff_heatmap(a, b, scale); }

}  // namespace ms
