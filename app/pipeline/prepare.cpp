#include "pipeline/prepare.h"

#include "core/error.h"
#include "render/aov.h"

namespace ms {

AssembleOptions FrameJob::assemble_options() const {
  AssembleOptions opts{shader_dir, defines, allow_include};
  if (aovs())
    for (const auto& d : aov_defines()) opts.defines.push_back(d);
  opts.specialize = specialize;
  opts.uniforms = uniforms;
  opts.graph_eval = graph_eval;
  opts.prune = prune;
  opts.cell_size = cell_size;
  return opts;
}

PreparedFrame prepare(const FrameJob& job, bool display) {
  PreparedFrame p;
  p.display = display;
  p.opts = job.assemble_options();
  p.in = load_input_scene(job.input, job.disable, p.opts, job.preset, job.set);
  if (job.verbose) report_scene_notes(p.in.scene, job.input.string());
  if (job.aovs() && p.in.shadertoy)
    fail_input("--aov needs a scene: a Shadertoy shader has no AOV outputs", job.input.string(), 0, "--aov");
  apply_shadertoy_options(p.in, job.shadertoy);
  if (job.fps) p.in.scene.shadertoy.fps = *job.fps;
  const Scene& scene = p.in.scene;
  p.fp.width = job.size.width > 0 ? job.size.width : scene.render.width;
  p.fp.height = job.size.height > 0 ? job.size.height : scene.render.height;
  p.fp.spp = job.spp > 0 ? job.spp : scene.render.spp;
  p.fp.aovs = job.aovs();
  p.fp.tile_size = job.tile_size;
  prepare_graph_shape(p.in.scene, p.opts);  // once: every pass and the GraphField take it from here
  p.post_src = assemble_still(p.in, p.opts, p.fp.spp, job.aovs(), display, p.fp.fused_post);
  return p;
}

double still_fps(const FrameJob& job, const LoadedInput& in) {
  return in.shadertoy || job.fps ? in.scene.shadertoy.fps : kSceneFps;
}

int buffer_targets(const LoadedInput& in) { return 2 * (static_cast<int>(in.passes.size()) - 1); }

}  // namespace ms
