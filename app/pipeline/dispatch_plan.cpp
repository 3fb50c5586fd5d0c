#include "pipeline/dispatch_plan.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <tuple>

namespace ms {

std::optional<std::pair<int, int>> next_probe_size(int w, int h, double ms) {
  if (ms >= kProbeMinMs || (w >= kProbeMaxWidth && h >= kProbeMaxHeight)) return std::nullopt;
  return std::make_pair(std::min(2 * w, kProbeMaxWidth), std::min(2 * h, kProbeMaxHeight));
}

DispatchProbe plan_dispatch(std::optional<ComputeGroup> given, const ProbeTimer& time) {
  DispatchProbe p;
  const ComputeGroup first = given.value_or(kProbeGroups[0]);
  int w = kProbeWidth, h = kProbeHeight;
  double compute_ms = 0.0;
  for (;;) {
    p.fragment_ms = time(Dispatch::fragment, {}, w, h);
    compute_ms = time(Dispatch::compute, first, w, h);
    const auto next = next_probe_size(w, h, std::min(p.fragment_ms, compute_ms));
    if (!next) break;
    std::tie(w, h) = *next;
  }
  p.width = w;
  p.height = h;
  p.compute.push_back({first, compute_ms});
  if (compute_ms < p.fragment_ms && !given)  // only compute's winner is worth its other shapes
    for (size_t i = 1; i < std::size(kProbeGroups); ++i)
      p.compute.push_back({kProbeGroups[i], time(Dispatch::compute, kProbeGroups[i], w, h)});
  const auto best = std::min_element(p.compute.begin(), p.compute.end(),
                                     [](const DispatchProbe::Timed& a, const DispatchProbe::Timed& b) { return a.ms < b.ms; });
  if (best->ms < p.fragment_ms) p.choice = {Dispatch::compute, best->group};
  else p.choice = {Dispatch::fragment, first};
  return p;
}

std::string describe_probe(const DispatchProbe& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "fragment %.2f ms, compute", p.fragment_ms);
  std::string s = buf;
  for (size_t i = 0; i < p.compute.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s %.2f%s (%s)", i ? "," : "", p.compute[i].ms, i ? "" : " ms",
                  group_name(p.compute[i].group).c_str());
    s += buf;
  }
  return s + " a frame at " + std::to_string(p.width) + "x" + std::to_string(p.height);
}

}  // namespace ms
