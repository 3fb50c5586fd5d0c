// --dispatch fragment|compute|auto, the hidden --compute-group WxH and
// --graph-eval,
// parsed once here into render/compute_frame.h's Dispatch (auto
// is chosen once a context exists: pipeline/dispatch_probe.h) and
// shader/compute_wrap.h's ComputeGroup; what a job may not draw with compute.
#pragma once
#include <optional>
#include <string>

#include "render/compute_frame.h"
#include "shader/compute_wrap.h"
#include "shader/graph_interp.h"

namespace ms {

// Throws bad_input (key "--dispatch") for anything but the three names.
Dispatch parse_dispatch(const std::string& name);
// "WxH" (each >= 1, W x H <= 1024) or "WxH/N" (ComputeGroup::stripe N,
// 0..1024); throws bad_input (key "--compute-group"). "" (not given):
// none, so compute draws 8x8 and auto measures the groups too.
std::optional<ComputeGroup> parse_compute_group(const std::string& text);

// --graph-eval inline|interpreter|auto (shader/graph_interp.h); throws
// bad_input (key "--graph-eval") for anything else.
GraphEval parse_graph_eval(const std::string& name);

}  // namespace ms
