// Builds the root GLSL for a scene (or the post pass) per the host <-> GLSL
// contract (#defines from the Scene, then the sdf_shaders/ includes) and runs
// it through preprocess(). No GL here.
#pragma once
#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene/features.h"
#include "scene/scene.h"
#include "preprocess/preprocess.h"
#include "shader/graph_interp.h"
#include "shader/scene_params.h"
#include "shader/specialize.h"

namespace ms {

struct GraphParts;

struct AssembleOptions {
  std::filesystem::path shader_dir;  // the sdf_shaders/ directory
  // Extra #defines (name, value) placed after the scene's own, e.g.
  // AOV_OUTPUTS or DEBUG_VIEW; a name the scene already defines is an error.
  std::vector<std::pair<std::string, std::string>> defines;
  // Directories an #include may read besides the scene's own directory
  // (a Shadertoy file's, for a bare .glsl) and shader_dir: --allow-include.
  // Nothing else is readable (PreprocessOptions::roots).
  std::vector<std::filesystem::path> allow_include;
  // Which code and values the scene shader compiles (shader/specialize.h):
  // render, bench and view fold (view keeps what the panel drags live),
  // --no-specialize (and this default) builds the generic shader.
  Specialization specialize = Specialization::generic;
  // Folded, the values the viewer's panel is dragging (shader/specialize.h
  // names them): their tables stay uniforms until the drag ends.
  std::vector<std::string> live = {};
  // --uniform NAME=VALUE: each becomes the initializer of the scene's ranged
  // uniform NAME (shader/scene_params.h), in the scene pass or in whichever
  // Shadertoy pass declares it; a name no pass declares is an error.
  std::vector<UniformValue> uniforms = {};  // (an initializer: no -Wmissing-field-initializers for AssembleOptions{a, b, c})
  // A graph scene's map(): straight GLSL or the interpreter (--graph-eval),
  // and with the interpreter the pruned grid unless --no-prune.
  GraphEval graph_eval = GraphEval::auto_;
  bool prune = true;
  float cell_size = 0.0f;  // the pruning grid's cells; 0: from the node count
  // A graph scene's [bounds] read from uniforms (uBoundsA, uBoundsB), not
  // folded: the viewer's, where they follow the graph's box and a saved
  // transform moves them without a compile (docs/viewer.md#graphs).
  bool bounds_uniforms = false;
  // The mesh exporter's compute pass (sdf_shaders/field_sample.glsl) in
  // place of main.frag: the same defines, library and map(), no image.
  bool field_sampler = false;
  // A graph scene's prepared shape (prepare_graph_shape()): every assemble_*
  // of the scene reads its map() from it; none derives it again.
  std::shared_ptr<const GraphParts> graph = nullptr;  // (an initializer, as above)
};

// A graph scene's prepared shape: how its map() is evaluated, the
// interpreter's buffers (empty when inline) and the pruning pass's compute
// shader (render/graph_field.h; empty unless pruned). The grid covers the
// scene's [bounds] box.
struct GraphParts {
  GraphEvalPlan plan;
  GraphBuffers buffers;
  ShaderSource prune_src;
  std::shared_ptr<const SceneGraph> graph;  // what it was derived from: a new pose finds what moved (graph_repose.h)
};
// Derives the shape from the scene's graph and opts' graph_eval, prune and
// cell_size. Callers go through prepare_graph_shape(), once per graph; a
// sequence of an animated graph calls it once per posed frame
// (pipeline/sequence.cpp), for the frame's buffers.
GraphParts graph_parts(const Scene& scene, const AssembleOptions& opts);
// Sets opts.graph to the scene's shape (null without a graph).
void prepare_graph_shape(const Scene& scene, AssembleOptions& opts);

// How many shapes graph_parts() has derived in this process: what tests
// count to prove a graph is prepared once per frame, not a timing.
struct AssembleStats {
  std::atomic<long> graph_parts{0};
};
AssembleStats& assemble_stats();

// The directories includes of a scene whose file is `scene_file` may read:
// its directory, opts.shader_dir and opts.allow_include.
std::vector<std::filesystem::path> include_roots(const std::filesystem::path& scene_file,
                                                 const AssembleOptions& opts);

// The scene's main-pass fragment shader: NUM_LIGHTS, NUM_MATERIALS,
// MAT_<NAME> per material (ids in TOML order), the quality defines, then
// prelude/primitives/operators/noise, the scene's map file (absolute) and main.frag.
// Source string 0 is shown as "<scene name>.frag (generated)".
// opts.specialize picks the generic shader or a specialized one
// (docs/specialization.md).
ShaderSource assemble_scene(const Scene& scene, const AssembleOptions& opts);
// The same with the scene_features() the caller already has (the viewer
// keeps them for features_changed()): the library is scanned once, not twice.
ShaderSource assemble_scene(const Scene& scene, const AssembleOptions& opts, const FeatureSet& features);

// What the scene uses (scene/features.h), with the library names scanned
// from its map, everything the map includes, the pipeline and the -D values.
// Reads the files like assemble_scene() and throws what it would.
FeatureSet scene_features(const Scene& scene, const AssembleOptions& opts);

// The post pass: TONEMAP (0 none, 1 Reinhard, 2 ACES) and ENCODE_SRGB, then
// post.frag.
// `flag_in_alpha`: a sample flagged non-finite keeps its colour and marks
// the pixel with a negative alpha (a Shadertoy Image pass, whose channels
// were converted one by one); otherwise the pixel is NaN (a scene's).
// `bloom`: BLOOM 1, the pass adds the bloom stage's target (render/bloom.h)
// before exposure; FrameParams::bloom must then be set.
ShaderSource assemble_post(Tonemap tonemap, bool encode_srgb, const AssembleOptions& opts, bool flag_in_alpha = false,
                           bool bloom = false);

// The bloom passes' fragment shaders (docs/post.md): bloom_extract.frag, or
// with `blur` bloom_blur.frag. No defines: their settings are uniforms.
ShaderSource assemble_bloom(bool blur, const AssembleOptions& opts);

// The extra defines (AssembleOptions::defines) of a scene shader that writes
// the output image itself, as assemble_post()'s pass would: FUSED_POST 1,
// TONEMAP and ENCODE_SRGB. For frames of one sample without AOVs
// (FrameParams::fused_post); saves the accumulation buffer and the post pass.
std::vector<std::pair<std::string, std::string>> fused_post_defines(Tonemap tonemap, bool encode_srgb);

// The shared vertex shader: one triangle covering the viewport, positions
// from gl_VertexID, no attributes (the host still binds an empty VAO).
std::string fullscreen_vertex_source();

// A float as a GLSL float literal that parses back to exactly `v`: the
// shortest round-trip digits, always with a '.' or an exponent ("100.0",
// "0.5", "1e-04"), negatives parenthesised. Throws ms::Error for inf/NaN.
std::string glsl_float(float v);

}  // namespace ms
