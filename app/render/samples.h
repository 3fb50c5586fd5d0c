// Sub-pixel sample positions for supersampling: stratified and deterministic
// (a fixed seed), so the same spp always gives the same image.
#pragma once
#include <vector>

#include <glm/vec2.hpp>

namespace ms {

// `spp` positions in [0,1)^2. spp = 1 is the pixel centre. Otherwise the pixel
// is split into a k x k grid (k = ceil(sqrt(spp))); spp distinct strata are
// chosen in a fixed shuffled order and jittered inside each with a fixed seed.
std::vector<glm::vec2> stratified_samples(int spp);

// Samples [begin, end) of an endless sequence in [0,1)^2 for accumulation
// without a limit: sample 0 is the pixel centre, then Roberts' R2 sequence
// (the plastic number's additive recurrence), low-discrepancy at every
// prefix, so the image refines evenly however long it runs.
std::vector<glm::vec2> open_samples(int begin, int end);

}  // namespace ms
