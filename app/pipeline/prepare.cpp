#include "pipeline/prepare.h"

#include "core/error.h"
#include "render/aov.h"
#include "scene/graph_animation.h"

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

namespace {

// A graph whose nodes move: interpreted, so that their values are buffers
// and a frame's new values compile nothing, with its bounds (its box, which
// moves) read from uniforms; posed at the still's time.
void animate_graph_options(const FrameJob& job, PreparedFrame& p) {
  if (job.graph_eval == GraphEval::inline_)
    fail_input("--graph-eval inline cannot animate graph nodes: it compiles their values in", job.input.string(), 0,
               "--graph-eval", "leave it auto (an animated graph is interpreted) or give interpreter");
  p.opts.graph_eval = GraphEval::interpreter;
  p.opts.bounds_uniforms = true;
  pose_graph_at(p.in.scene, job.time ? *job.time : p.in.scene.render.time);
}

}  // namespace

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
  if (animates_graph(p.in.scene)) animate_graph_options(job, p);
  prepare_graph_shape(p.in.scene, p.opts);  // once: every pass and the GraphField take it from here
  p.post_src = assemble_still(p.in, p.opts, p.fp.spp, job.aovs(), display, p.fp.fused_post);
  return p;
}

double still_fps(const FrameJob& job, const LoadedInput& in) {
  return in.shadertoy || job.fps ? in.scene.shadertoy.fps : kSceneFps;
}

int buffer_targets(const LoadedInput& in) { return 2 * (static_cast<int>(in.passes.size()) - 1); }

}  // namespace ms
