// --dispatch fragment|compute|auto and the hidden --compute-group WxH
// (issue 18): parsed once here into render/compute_frame.h's Dispatch and
// shader/compute_wrap.h's ComputeGroup; what a job may not draw with compute.
#pragma once
#include <string>

#include "render/compute_frame.h"
#include "shader/compute_wrap.h"

namespace ms {

struct LoadedInput;

// Throws bad_input (key "--dispatch") for anything but the three names.
Dispatch parse_dispatch(const std::string& name);
// "WxH", each >= 1, W x H <= 1024; throws bad_input (key "--compute-group").
ComputeGroup parse_compute_group(const std::string& text);
// What `auto` draws with: the fragment pass for now (no probe yet).
Dispatch resolve_dispatch(Dispatch d);
// Throws bad_input (key "--dispatch") when `d` is compute and the input is
// not an SDF scene (a Shadertoy shader or a project with buffers). A still
// drawn in tiles (cli/tiled_render.h) is drawn by compute too: `tiled_still`
// is kept for the callers and no longer refuses.
void check_compute_input(Dispatch d, const LoadedInput& in, bool tiled_still);

}  // namespace ms
