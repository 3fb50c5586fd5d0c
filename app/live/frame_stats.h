// Rolling frame times for the viewer's graph and its "median over the last
// second". Pure bookkeeping, no GL: the loop feeds it CPU and GPU times.
#pragma once
#include <cstddef>
#include <deque>
#include <vector>

namespace ms::live {

class TimeSeries {
 public:
  explicit TimeSeries(std::size_t capacity = 240) : capacity_(capacity) {}
  // A sample of `ms` milliseconds taken at `t` seconds (any steady clock).
  void add(double t, double ms);
  // Median of the samples taken in (now - window, now]; 0 when there are none.
  double median(double now, double window = 1.0) const;
  // The last up to `capacity` samples, oldest first (for ImGui::PlotLines).
  std::vector<float> values() const;
  bool empty() const { return samples_.empty(); }

 private:
  struct Sample {
    double t, ms;
  };
  std::size_t capacity_;
  std::deque<Sample> samples_;
};

// Median of `v` (the mean of the two middle values for an even count); 0 for none.
double median_of(std::vector<double> v);

}  // namespace ms::live
