// The [quality] table's keys, types and ranges: one list, read by the scene
// loader (load.cpp) and used by the presets (quality.cpp) to carry a file's
// explicit keys over to another preset. `preset` itself is read by hand.
#pragma once
#include "scene/scene.h"
#include "scene/toml_read.h"

namespace ms {

inline const Field<Quality> kQualityFields[] = {
    {"max_steps", &Quality::max_steps, Range::closed(1, 100000)},
    {"max_distance", &Quality::max_distance, Range::above(0)},
    {"hit_tolerance", &Quality::hit_tolerance, Range::at_least(0)},
    {"hit_epsilon", &Quality::hit_epsilon, Range::above(0)},
    {"lipschitz", &Quality::lipschitz, Range::at_least(1)},
    {"omega", &Quality::omega, {1.0, 2.0, false, true}},  // [1, 2): 2 and up can oscillate forever
    {"shadow_steps", &Quality::shadow_steps, Range::closed(0, 10000)},
    {"ao_taps", &Quality::ao_taps, Range::closed(0, 64)},
    {"bounces", &Quality::bounces, Range::closed(0, 16)},
    {"shadows", &Quality::shadows},
    {"ao", &Quality::ao},
    {"reflections", &Quality::reflections},
    {"checker_filter", &Quality::checker_filter},
    {"bounds", &Quality::bounds},
    {"analytic_planes", &Quality::analytic_planes},
};

}  // namespace ms
