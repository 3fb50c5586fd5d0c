// Order statistics for bench: frame times and per-pixel counts. Pure.
#pragma once
#include <vector>

namespace ms {

// min, median, p95, max and mean of a sample. Percentiles use the
// nearest-rank method (the value at rank ceil(p/100 * n) of the sorted
// sample, so p95 of 20 frames is the 19th fastest: always a measured value);
// the median is the mean of the two middle values for even n. All 0 for an
// empty sample.
struct Summary {
  double min = 0, median = 0, p95 = 0, max = 0, mean = 0;
};
Summary summarize(std::vector<double> v);

// Nearest-rank percentile p in (0, 100] of a sorted sample; 0 when empty.
double percentile_sorted(const std::vector<double>& sorted, double p);

// Mean, p99 (nearest rank) and max of per-pixel counts (steps, evaluations).
struct CountStats {
  double mean = 0, p99 = 0, max = 0;
};
CountStats count_stats(std::vector<double> v);

}  // namespace ms
