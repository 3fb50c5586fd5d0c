#include "pipeline/bounds_report.h"

#include <cstdio>

#include "core/error.h"
#include "scene/graph_scene.h"

namespace ms {

void BoundsReport::check(const std::string& scene_file, const Scene& posed, const AssembleOptions& opts,
                         const UniformFn& set_uniforms, bool strict) {
  if (!strict && warned_.count(scene_file) > 0) return;  // once per scene: the rest would say the same
  // A graph's box says exactly what it may draw: no probe needed.
  const std::string overhang = posed.bounds.kind == BoundsKind::box ? graph_overhang(posed) : std::string();
  const std::string w =
      !overhang.empty() ? scene_file + ": warning: the scene graph's box pokes out of [bounds] " + overhang +
                              ": what lies there is cut off; grow [bounds] or delete it (a graph's box is the default)"
      : posed.graph  // a sphere is not probed: the interpreter's buffers are not bound here
          ? std::string()
          : bounds_warning(scene_file, check_bounds(posed, opts, set_uniforms, &probes_));
  if (w.empty()) return;
  if (strict) {
    const std::string prefix = scene_file + ": warning: ";
    const std::string what = w.rfind(prefix, 0) == 0 ? w.substr(prefix.size()) : w;
    throw Error({Exit::threshold, scene_file, 0, "--strict", what + "; the image is not written", {}, {}});
  }
  warned_.insert(scene_file);
  std::fprintf(stderr, "marchstudio: %s (--strict makes this an error)\n", w.c_str());
}

}  // namespace ms
