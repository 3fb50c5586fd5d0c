#include "live/frame_stats.h"

#include <algorithm>

namespace ms::live {

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  if (v.size() % 2) return v[mid];
  const double hi = v[mid];
  const double lo = *std::max_element(v.begin(), v.begin() + mid);
  return 0.5 * (lo + hi);
}

void TimeSeries::add(double t, double ms) {
  samples_.push_back({t, ms});
  while (samples_.size() > capacity_) samples_.pop_front();
}

double TimeSeries::median(double now, double window) const {
  std::vector<double> v;
  for (auto it = samples_.rbegin(); it != samples_.rend() && it->t > now - window; ++it)
    if (it->t <= now) v.push_back(it->ms);
  return median_of(std::move(v));
}

std::vector<float> TimeSeries::values() const {
  std::vector<float> out;
  out.reserve(samples_.size());
  for (const Sample& s : samples_) out.push_back(static_cast<float>(s.ms));
  return out;
}

}  // namespace ms::live
