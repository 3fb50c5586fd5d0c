#include "cli/dispatch_flag.h"

#include <cstdio>

#include "cli/input.h"
#include "core/error.h"

namespace ms {

Dispatch parse_dispatch(const std::string& name) {
  if (name == "fragment") return Dispatch::fragment;
  if (name == "compute") return Dispatch::compute;
  if (name == "auto") return Dispatch::automatic;
  fail_input("--dispatch '" + name + "' is not one of fragment, compute, auto", {}, 0, "--dispatch");
}

std::optional<ComputeGroup> parse_compute_group(const std::string& text) {
  if (text.empty()) return std::nullopt;
  ComputeGroup g;
  char x = 0, slash = 0, extra = 0;
  const int n = std::sscanf(text.c_str(), "%d%c%d%c%d%c", &g.x, &x, &g.y, &slash, &g.stripe, &extra);
  if ((n != 3 && n != 5) || (x != 'x' && x != 'X') || (n == 5 && slash != '/') || g.x < 1 || g.y < 1 ||
      g.x * g.y > 1024 || g.stripe < 0 || g.stripe > 1024)
    fail_input("--compute-group '" + text + "' must be WxH with 1..1024 invocations, e.g. 8x8, or WxH/N for stripes of N group rows",
               {}, 0, "--compute-group");
  return g;
}

void check_compute_input(Dispatch d, const LoadedInput& in, bool /*tiled_still: compute draws tiles too*/) {
  if (d != Dispatch::compute) return;
  // The frame's pass as compute (render/compute_frame.h); buffer and Cube A
  // passes stay fragment passes. Derivative calls, and implicit-LOD lookups
  // with a mipmapped input, are refused here at their file:line.
  (void)compute_source(in.passes.back());
}

}  // namespace ms
