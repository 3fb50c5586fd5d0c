// What made an image, as a fingerprint written into every image `render`
// writes (io/image_io.h) and checked when a sequence resumes, so a rerun
// never keeps a frame made from other inputs (docs/animation.md#fingerprints).
//
//   const std::string job = job_fingerprint(in, fp, post_src, aov_names, fps);
//   add_fingerprint(meta, frame_fingerprint(job, f, time));
//
// The job part hashes the input file's bytes and its --set overrides,
// every pass's assembled shader (the map, includes, defines, --uniform
// values, quality and specialization are in that text), each texture's
// pixels and sampler, the environment map's irradiance, the post shader,
// the size, samples, exposure, AOVs, frame rate and iMouse, and the
// program's version; a frame adds its number and its time.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "pipeline/input.h"
#include "render/frame.h"
#include "preprocess/preprocess.h"

namespace ms {

std::string job_fingerprint(const LoadedInput& in, const FrameParams& fp, const ShaderSource& post,
                            const std::vector<std::string>& aovs, double fps);
std::string frame_fingerprint(const std::string& job, int frame, float time);

// What every image the pipeline writes carries: Software, "<input file>
// t=<time> spp=<spp>" (" frame=<n>" for a sequence's frame) and the
// fingerprint of what made it.
ImageMetadata frame_metadata(const std::filesystem::path& input, float time, int spp,
                             const std::string& fingerprint, std::optional<int> frame = std::nullopt);

}  // namespace ms
