// Whether a job's frames have bloom ([post.bloom], docs/post.md), and the
// stage that draws it. An .exr output keeps the pre-bloom linear image
// unless the scene says exr = true; --disable bloom and a Shadertoy shader
// have none. Without bloom nothing changes: no passes, no BLOOM in post.
#pragma once
#include <memory>

#include "pipeline/input.h"
#include "render/bloom.h"
#include "render/program_cache.h"

namespace ms {

// Whether the frames of `in` written to a display (8-bit) or linear output bloom.
bool bloom_on(const LoadedInput& in, bool display);

// The stage for the frames of `in`, its programs from `cache` (the context
// current); nullptr when bloom_on() is false.
std::unique_ptr<BloomStage> make_bloom_stage(const LoadedInput& in, bool display, const AssembleOptions& opts,
                                             ProgramCache& cache);

}  // namespace ms
