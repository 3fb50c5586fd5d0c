// Keyframe animation: [[animation]] tables in a scene file, each driving one
// camera, light, material, sky or render value over time
// (docs/scene-format.md#animation). Read and checked with the rest of the
// scene (scene/load.cpp calls read_animation_track); applied per frame by
// animated(), which the renderer calls with the frame's time.
#pragma once
#include <array>
#include <string>

#include <toml++/toml.h>

#include "scene/scene.h"
#include "scene/toml_read.h"

namespace ms {

// Read one [[animation]] table at `path` ("animation[2]"): its target must
// name a value that exists in `scene` (lights and materials are read
// first), not be animated already, and its keys must be [time, values...]
// rows with the target's arity, finite, in the target's range, times
// strictly increasing. Throws bad_input naming file:line and the key.
AnimationTrack read_animation_track(const Reader& r, const toml::table& t, const std::string& path, Scene& scene);

// The track's value(s) at `time`: held constant before the first key and
// after the last; between keys a linear blend, or for "smooth" a blend
// eased by smoothstep (u*u*(3-2u)), so the motion starts and stops at each
// key with zero velocity and never leaves the range of its two keys.
// Computed in double. Only the first `track.arity` entries are meaningful.
std::array<double, 3> evaluate(const AnimationTrack& track, double time);

// `scene` with every track applied at `time` (seconds). Throws bad_input
// when the result cannot be rendered at that time: the camera's target on
// its position or its up along the view, or a zero-length light direction.
Scene animated(const Scene& scene, double time);

// The value an animation target names ("materials[0].color"), read into
// *value (1 or 3 entries, *arity says) and, when `set`, replaced by *value
// first. Returns the error ("unknown animation target ...") or "" (the
// viewer's scripted --drag uses it).
std::string target_value(Scene& scene, const std::string& target, std::array<double, 3>* value, int* arity,
                         bool set);

}  // namespace ms
