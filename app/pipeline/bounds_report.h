// The [bounds] check (render/bounds_check.h) on the paths a farm runs:
// every `render` still, each job of a --jobs batch and each frame of a
// --frames sequence. Geometry crossing the bounds is cut off, so it is a
// warning once per scene (a batch of forty jobs of one scene warns once),
// or with --strict an error, exit 1, before anything is written.
//
//   BoundsReport bounds;  // declared after the GL context: its programs die first
//   bounds.check(input, posed, opts, set_uniforms, strict);  // throws with strict
#pragma once
#include <set>
#include <string>

#include "render/bounds_check.h"
#include "render/program_cache.h"

namespace ms {

class BoundsReport {
 public:
  // Probes `posed` (a Shadertoy input or a scene without bounds passes)
  // unless `scene_file` was already warned about; prints the one-line
  // warning, or with `strict` throws it as an exit-1 error naming --strict.
  void check(const std::string& scene_file, const Scene& posed, const AssembleOptions& opts,
             const UniformFn& set_uniforms, bool strict);

 private:
  std::set<std::string> warned_;
  ProgramCache probes_{4};  // the probe's program, kept from frame to frame and job to job
};

}  // namespace ms
