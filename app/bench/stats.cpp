#include "bench/stats.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ms {

double percentile_sorted(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  const double n = static_cast<double>(sorted.size());
  const size_t rank = static_cast<size_t>(std::ceil(std::clamp(p, 0.0, 100.0) / 100.0 * n));
  return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

static double mean_of(const std::vector<double>& v) {
  // long double: a 4K frame has 8M pixels, and float-sized sums drift.
  long double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : static_cast<double>(s / static_cast<long double>(v.size()));
}

Summary summarize(std::vector<double> v) {
  Summary s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  s.min = v.front();
  s.max = v.back();
  s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  s.p95 = percentile_sorted(v, 95.0);
  s.mean = mean_of(v);
  return s;
}

CountStats count_stats(std::vector<double> v) {
  CountStats c;
  if (v.empty()) return c;
  c.mean = mean_of(v);
  std::sort(v.begin(), v.end());
  c.p99 = percentile_sorted(v, 99.0);
  c.max = v.back();
  return c;
}

}  // namespace ms
