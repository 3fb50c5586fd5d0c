// --dispatch fragment|compute|auto and the hidden --compute-group WxH,
// parsed once here into render/compute_frame.h's Dispatch (auto
// is chosen once a context exists: cli/dispatch_probe.h) and
// shader/compute_wrap.h's ComputeGroup; what a job may not draw with compute.
#pragma once
#include <optional>
#include <string>

#include "render/compute_frame.h"
#include "shader/compute_wrap.h"

namespace ms {

struct LoadedInput;

// Throws bad_input (key "--dispatch") for anything but the three names.
Dispatch parse_dispatch(const std::string& name);
// "WxH" (each >= 1, W x H <= 1024) or "WxH/N" (ComputeGroup::stripe N,
// 0..1024); throws bad_input (key "--compute-group"). "" (not given):
// none, so compute draws 8x8 and auto measures the groups too.
std::optional<ComputeGroup> parse_compute_group(const std::string& text);
// Throws bad_input (key "--dispatch", at file:line) when `d` is compute and
// the frame's pass cannot run as one (render/compute_frame.h's
// compute_source: derivative calls, implicit-LOD lookups of a mipmapped
// input). Before any context: nothing is drawn or written. `tiled_still` is
// kept for the callers: compute draws tiled stills too.
void check_compute_input(Dispatch d, const LoadedInput& in, bool tiled_still);

}  // namespace ms
