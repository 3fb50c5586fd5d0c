// AOVs (arbitrary output variables): what the main pass writes beside the
// colour when assembled with AOV_OUTPUTS 1, their channel names, and the
// debug-view colour ramps mirrored from sdf_shaders/aov.glsl. No GL here.
// Layout and conventions: docs/shader-library.md ("AOVs and debug views").
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "io/image.h"

namespace ms {

// Every channel FrameRenderer::read_aovs() returns, in this order, each the
// average over the frame's samples. Per-hit channels (Z, N.*, material,
// shadow, ao) are 0 for a miss; `hit` is the fraction of samples that hit.
//   hit, Z (ray distance t, world units), N.x N.y N.z (shading normal, world),
//   steps (primary), material (id), shadow (mean light visibility), ao,
//   shadow_steps, reflection_steps, sdf_evals (map() calls), step_cap (0/1)
extern const std::vector<std::string> kAovChannels;

// The names `render --aov` accepts: depth, normal, steps, material, shadow,
// ao, cost (shadow_steps, reflection_steps, sdf_evals, step_cap), hit.
extern const std::vector<std::string> kAovNames;

// The channels for a list of --aov names, in kAovChannels order without
// duplicates, always starting with `hit` (it tells a miss from a zero).
// Throws bad_input (key "--aov") naming an unknown or empty entry.
std::vector<std::string> aov_channels(const std::vector<std::string>& names);

// The defines that turn the AOV targets on (for AssembleOptions::defines).
std::vector<std::pair<std::string, std::string>> aov_defines();

// The named channels of `src`, in the order given; throws std::out_of_range
// naming a missing channel (a programming error, not user input).
Image select_channels(const Image& src, const std::vector<std::string>& names);

// a's channels followed by b's, pixel by pixel; sizes must match.
Image append_channels(const Image& a, const Image& b);
// The AOV render targets after the colour (locations 1..3: outGeom, outMisc, outCost).
constexpr int kAovTargets = 3;
// The AOV image from the accumulated targets as read back (RGBA floats,
// top row first, `samples` added into each): target 0's alpha counts the
// hits, targets 1..kAovTargets hold 4 channels each in kAovChannels order
// after `hit`. Channels kAovChannels, each the mean over the samples.
Image aovs_from_targets(const std::vector<std::vector<float>>& targets, int width, int height, int samples);

// DEBUG_VIEW 1's fixed log scale, exactly as stepsHeatPosition() in
// aov.glsl: log2(steps + 1) / 8 clamped to [0,1] (3 -> .25, 15 -> .5,
// 63 -> .75, 255 -> 1). For drawing a legend.
float steps_heat_position(float steps);
// heatRamp(): 5 linear stops at 0, .25, .5, .75, 1 (dark blue, blue, green,
// yellow, red), linear colour.
glm::vec3 heat_ramp(float x);
// DEBUG_VIEW 3's grey, exactly as depthShade() in aov.glsl: 1 at t = 0, 0 at
// max_dist, 1 - log2(1 + t) / log2(1 + max_dist). For the legend and tests.
float depth_shade(float t, float max_dist);

}  // namespace ms
