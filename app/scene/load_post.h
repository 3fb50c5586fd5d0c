// [post] and its [post.bloom] table (docs/post.md). The scene loader
// (load.cpp) calls read_post(); the field list is here so it can be tested.
#pragma once
#include "scene/scene.h"
#include "scene/toml_read.h"

namespace ms {

inline const Field<Bloom> kBloomFields[] = {
    {"threshold", &Bloom::threshold, Range::at_least(0)},
    {"intensity", &Bloom::intensity, Range::at_least(0)},
    {"radius", &Bloom::radius, Range{0, 256, true, false}},
    {"scale", &Bloom::scale, Range::closed(0.05, 1)},
    {"passes", &Bloom::passes, Range::closed(1, 8)},
    {"exr", &Bloom::exr},
};

// [post] holds only tables ([post.bloom]); each key is checked, each value
// range-checked with file:line:key errors. A present [post.bloom] sets
// bloom.enabled; without it the scene has no bloom at all.
void read_post(const Reader& r, const toml::table& root, Bloom& bloom);

}  // namespace ms
