#include "shader/assemble.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/error.h"
#include "preprocess/glsl_scan.h"
#include "scene/graph_unary.h"
#include "scene/graph_vocab.h"
#include "shader/graph_glsl.h"
#include "shader/specialize.h"

namespace ms {

namespace fs = std::filesystem;

std::string glsl_float(float v) {
  if (!std::isfinite(v)) fail_input("cannot write a non-finite number into a shader");
  char buf[64];
  // Shortest digits that round-trip through a correctly rounded float parse,
  // which is what GLSL compilers do for float literals.
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, end);
  // "100" would be an int in GLSL; "1e-04" is already a float literal.
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  if (s[0] == '-') s = "(" + s + ")";
  return s;
}

namespace {

void define(std::string& out, const std::string& name, const std::string& value) {
  out += "#define " + name + " " + value + "\n";
}

void define(std::string& out, const std::string& name, int value) { define(out, name, std::to_string(value)); }

std::string scene_display_name(const Scene& scene) {
  if (!scene.name.empty()) return scene.name;
  if (!scene.file.empty()) return scene.file.stem().string();
  return "scene";
}

// MAT_<NAME>; the loader already validated names, but a bad one here would
// otherwise surface as a confusing GLSL error far from its cause.
std::string material_macro(const Scene& scene, size_t i) {
  const std::string& name = scene.materials[i].name;
  bool ok = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
  std::string macro = "MAT_";
  for (char c : name) {
    ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    macro += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  if (!ok)
    fail_input("material name '" + name + "' is not a GLSL identifier", display_path(scene.file), 0,
               "materials[" + std::to_string(i) + "].name", "use letters, digits and '_', not starting with a digit");
  return macro;
}

// The root includes the map file by absolute path; a quote or newline in it
// would end the #include early. It must lie inside the include roots like
// any include (checked here for an error that names scene.map).
std::string map_include_path(const Scene& scene, const std::vector<fs::path>& roots) {
  std::error_code ec;
  fs::path p = fs::absolute(scene.map_file, ec);
  if (!scene.map_file.empty() && !within_roots(p, roots))
    fail_input("the map file '" + display_path(p) + "' is outside the directories includes may read",
               display_path(scene.file), 0, "scene.map",
               "allowed: " + describe_roots(roots) + "; widen with --allow-include DIR");
  if (scene.map_file.empty() || ec || !fs::is_regular_file(p, ec))
    fail_input("cannot find the map file '" + scene.map_file.generic_string() + "'", display_path(scene.file), 0,
               "scene.map", "the path is relative to the scene file");
  std::string s = p.lexically_normal().generic_string();
  if (s.find_first_of("\"\n\r") != std::string::npos)
    fail_input("the map file path contains a quote or newline", display_path(scene.file), 0, "scene.map");
  return s;
}

// The scene's map(): the map file's #include, or the graph's generated code.
std::string map_code(const Scene& scene, const std::vector<fs::path>& roots, const AssembleOptions& opts) {
  if (scene.graph) {
    // A programming error, not bad input: the pipeline prepares the shape first.
    if (!opts.graph) throw std::logic_error("a graph scene assembled before prepare_graph_shape()");
    const GraphParts& parts = *opts.graph;
    return parts.plan.interpret ? graph_map_interpreter(*scene.graph, parts.plan, parts.buffers)
                                : graph_map_inline(*scene.graph);
  }
  return "#include \"" + map_include_path(scene, roots) + "\"\n";
}

PreprocessOptions library_options(const AssembleOptions& opts) {
  PreprocessOptions p;
  p.include_dirs = {opts.shader_dir};
  return p;
}

// What the scene's includes may read. A scene made in memory (no file)
// reads from its map file's directory.
PreprocessOptions scene_options(const Scene& scene, const AssembleOptions& opts) {
  PreprocessOptions popts = library_options(opts);
  popts.roots = include_roots(scene.file.empty() ? scene.map_file : scene.file, opts);
  return popts;
}

// The GLSL whose library references (sd*, op*, dom*, noise*) decide which
// library functions a specialized shader keeps: the map with everything it
// includes, the pipeline (main.frag and its files) and the -D values. Only
// the library files themselves are left out: they are included first, so
// #pragma once skips them afterwards.
std::string library_users(const std::string& map, const AssembleOptions& opts, PreprocessOptions popts) {
  popts.model_driver = false;  // every include, whatever the #ifs: the scan over-approximates
  const std::string marker = "// marchstudio: library users start here\n";
  const std::string root = "#include \"primitives.glsl\"\n#include \"operators.glsl\"\n#include \"noise.glsl\"\n" + marker +
                           map + "#include \"main.frag\"\n";
  std::string text = preprocess(root, "library scan (generated)", opts.shader_dir, popts).text;
  text.erase(0, text.find(marker));
  for (const auto& d : opts.defines) text += "\n" + d.second;
  return text;
}

std::string glsl_vec4(glm::vec3 v, float w) {
  return "vec4(" + glsl_float(v.x) + ", " + glsl_float(v.y) + ", " + glsl_float(v.z) + ", " + glsl_float(w) + ")";
}

// The tracer's analytic geometry (sdf_shaders/bounds.glsl): the declared
// planes (exact, or marched with analytic_planes off: the textbook way), the
// bounding volume when quality.bounds is on, and the over-relaxation.
// `uniforms`: a graph scene's bounds are uniforms (AssembleOptions::bounds_uniforms).
void define_tracer_geometry(std::string& root, const Scene& scene, bool uniforms) {
  const Quality& q = scene.quality;
  define(root, "OMEGA", glsl_float(q.omega));
  define(root, "NUM_PLANES", static_cast<int>(scene.planes.size()));
  define(root, "ANALYTIC_PLANES", q.analytic_planes ? 1 : 0);
  if (!scene.planes.empty()) {
    std::string list, mats;
    for (const Plane& p : scene.planes) {
      list += (list.empty() ? "" : ", ") + glsl_vec4(p.normal, p.offset);
      mats += (mats.empty() ? "" : ", ") + std::to_string(p.material_id);
    }
    define(root, "PLANE_LIST", list);
    define(root, "PLANE_MATERIALS", mats);
  }
  const Bounds& b = scene.bounds;
  const int kind = !q.bounds ? 0 : b.kind == BoundsKind::sphere ? 1 : b.kind == BoundsKind::box ? 2 : 0;
  define(root, "BOUNDS_KIND", kind);
  if (kind != 0 && uniforms && scene.graph) {
    define(root, "BOUNDS_UNIFORMS", 1);  // sdf_shaders/bounds.glsl
    return;
  }
  if (kind == 1) define(root, "BOUNDS_A", glsl_vec4(b.center, b.radius));
  if (kind == 2) {
    define(root, "BOUNDS_A", glsl_vec4(b.min, 0.0f));
    define(root, "BOUNDS_B", glsl_vec4(b.max, 0.0f));
  }
}

// The pruning pass's compute shader: the library functions the graph uses,
// then its generated source.
ShaderSource assemble_graph_prune(const Scene& scene, const GraphParts& parts, const AssembleOptions& opts) {
  std::string root = "#version 450 core\n#define MS_LIBRARY_SUBSET 1\n";
  std::set<std::string> used;
  for (const GraphNode& n : scene.graph->nodes) {
    if (!n.unary) {
      used.insert(std::string(n.leaf ? graph_primitives()[static_cast<std::size_t>(n.fn)].name
                                     : graph_operators()[static_cast<std::size_t>(n.fn)].name));
      continue;
    }
    const GraphUnary& u = graph_unaries()[static_cast<std::size_t>(n.fn)];
    for (std::string_view f : {u.begin, u.end})
      if (!f.empty()) used.insert(std::string(f));
    if (u.copies) used.insert("opCopyFloor");
  }
  for (std::string name : used) {
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    define(root, "USE_" + name, 1);
  }
  root += "#include \"common.glsl\"\n#include \"primitives.glsl\"\n#include \"operators.glsl\"\n";
  root += graph_prune_source(*scene.graph, parts.plan, parts.buffers);
  return preprocess(root, "graph pruning pass (generated)", opts.shader_dir, library_options(opts));
}

}  // namespace

AssembleStats& assemble_stats() {
  static AssembleStats stats;
  return stats;
}

GraphParts graph_parts(const Scene& scene, const AssembleOptions& opts) {
  GraphParts parts;
  if (!scene.graph) return parts;
  ++assemble_stats().graph_parts;
  parts.graph = scene.graph;
  const GraphBox box = scene.bounds.kind == BoundsKind::box ? GraphBox{scene.bounds.min, scene.bounds.max}
                                                            : scene.graph->root_node().box;
  parts.plan = plan_graph_eval(*scene.graph, opts.graph_eval, opts.prune, box, opts.cell_size);
  if (parts.plan.interpret) parts.buffers = graph_buffers(*scene.graph);
  if (parts.plan.pruned()) parts.prune_src = assemble_graph_prune(scene, parts, opts);
  return parts;
}

void prepare_graph_shape(const Scene& scene, AssembleOptions& opts) {
  opts.graph = scene.graph ? std::make_shared<const GraphParts>(graph_parts(scene, opts)) : nullptr;
}

std::vector<fs::path> include_roots(const fs::path& scene_file, const AssembleOptions& opts) {
  std::error_code ec;
  fs::path dir = fs::absolute(scene_file, ec).parent_path();
  std::vector<fs::path> roots = {dir, opts.shader_dir};
  roots.insert(roots.end(), opts.allow_include.begin(), opts.allow_include.end());
  return roots;
}

FeatureSet scene_features(const Scene& scene, const AssembleOptions& opts) {
  const PreprocessOptions popts = scene_options(scene, opts);
  return derive_features(scene, library_users(map_code(scene, popts.roots, opts), opts, popts));
}

ShaderSource assemble_scene(const Scene& scene, const AssembleOptions& opts) {
  return assemble_scene(scene, opts,
                        opts.specialize == Specialization::generic ? FeatureSet{} : scene_features(scene, opts));
}

ShaderSource assemble_scene(const Scene& scene, const AssembleOptions& opts, const FeatureSet& features) {
  if (scene.materials.empty())
    fail_input("a scene needs at least one material", display_path(scene.file), 0, "materials");
  const PreprocessOptions popts = scene_options(scene, opts);
  const std::string map = map_code(scene, popts.roots, opts);
  // [sky] environment is read later (render/environment.h): a medium, confined as one.
  if (!scene.sky.environment.empty())
    confine_media(scene.sky.environment, media_roots(scene.file, {}, opts.allow_include),
                  "environment '" + scene.sky.environment.generic_string() + "'", display_path(scene.file),
                  "sky.environment");
  // Generic: the scene's own quality, nothing else. Otherwise only the
  // features the scene uses, and folded values (docs/specialization.md).
  const Specialized sp =
      specialize(scene, opts.specialize == Specialization::generic ? FeatureSet{} : features, opts.specialize,
                 opts.live);
  const Quality& q = sp.quality;
  std::string root = "#version 450 core\n";
  root += "// generated by marchstudio for scene '" + comment_label(scene_display_name(scene)) + "'\n";
  define(root, "NUM_LIGHTS", static_cast<int>(scene.lights.size()));
  if (!scene.sky.environment.empty()) define(root, "ENV_MAP", 1);  // render/environment.h; absent: none of its code
  define(root, "NUM_MATERIALS", static_cast<int>(scene.materials.size()));
  for (size_t i = 0; i < scene.materials.size(); ++i) define(root, material_macro(scene, i), static_cast<int>(i));
  define(root, "MAX_STEPS", q.max_steps);
  define(root, "MAX_DIST", glsl_float(q.max_distance));
  define(root, "HIT_TOLERANCE", glsl_float(q.hit_tolerance));
  define(root, "HIT_EPSILON", glsl_float(q.hit_epsilon));
  define(root, "LIPSCHITZ", glsl_float(q.lipschitz));
  define(root, "SHADOW_STEPS", q.shadow_steps);
  define(root, "AO_TAPS", q.ao_taps);
  define(root, "MAX_BOUNCES", q.bounces);
  define(root, "ENABLE_SHADOWS", q.shadows ? 1 : 0);
  define(root, "ENABLE_AO", q.ao ? 1 : 0);
  define(root, "ENABLE_REFLECTIONS", q.reflections ? 1 : 0);
  define(root, "ENABLE_CHECKER_FILTER", q.checker_filter ? 1 : 0);
  define_tracer_geometry(root, scene, opts.bounds_uniforms);
  root += sp.defines;
  for (const auto& [name, value] : opts.defines) {
    if (root.find("#define " + name + " ") != std::string::npos)
      fail_input("define '" + name + "' is already set by the scene", display_path(scene.file), 0, name);
    define(root, name, value);
  }
  if (opts.field_sampler) define(root, "FIELD_SAMPLER", 1);
  root += "#include \"prelude.glsl\"\n";
  root += sp.constants;
  root += "#include \"primitives.glsl\"\n";
  root += "#include \"operators.glsl\"\n";
  root += "#include \"noise.glsl\"\n";
  root += map;
  root += opts.field_sampler ? "#include \"field_sample.glsl\"\n" : "#include \"main.frag\"\n";
  ShaderSource src = preprocess(root, scene_display_name(scene) + (opts.field_sampler ? ".comp" : ".frag") + " (generated)",
                                opts.shader_dir, popts);
  // Without it the driver would blame the library line that calls map().
  if (const std::string code = strip_comments(src.text); find_definition(code, "map", "vec2") == std::string::npos) {
    if (const std::string type = definition_type(code, "map"); !type.empty())
      fail_input("map() returns " + type + "; it must return vec2 (distance, material id)", display_path(scene.file), 0,
                 "scene.map");
    fail_input("the map file defines no map() function", display_path(scene.file), 0, "scene.map",
               "define vec2 map(vec3 p), returning the distance and a material id");
  }
  if (!opts.uniforms.empty())
    check_uniforms_found(opts.uniforms, set_uniform_defaults(src.text, opts.uniforms), parse_scene_params(src.text));
  return src;
}

// tonemap.glsl's TONEMAP values.
static int tonemap_id(Tonemap tonemap) {
  return tonemap == Tonemap::none ? 0 : tonemap == Tonemap::reinhard ? 1 : 2;
}

ShaderSource assemble_post(Tonemap tonemap, bool encode_srgb, const AssembleOptions& opts, bool flag_in_alpha,
                           bool bloom) {
  std::string root = "#version 450 core\n";
  define(root, "TONEMAP", tonemap_id(tonemap));
  define(root, "ENCODE_SRGB", encode_srgb ? 1 : 0);
  define(root, "FLAG_IN_ALPHA", flag_in_alpha ? 1 : 0);
  define(root, "BLOOM", bloom ? 1 : 0);
  root += "#include \"post.frag\"\n";
  return preprocess(root, "post pass (generated)", opts.shader_dir, library_options(opts));
}

ShaderSource assemble_bloom(bool blur, const AssembleOptions& opts) {
  const std::string file = blur ? "bloom_blur.frag" : "bloom_extract.frag";
  return preprocess("#version 450 core\n#include \"" + file + "\"\n", file + " (generated)", opts.shader_dir,
                    library_options(opts));
}

std::vector<std::pair<std::string, std::string>> fused_post_defines(Tonemap tonemap, bool encode_srgb) {
  return {{"FUSED_POST", "1"}, {"TONEMAP", std::to_string(tonemap_id(tonemap))}, {"ENCODE_SRGB", encode_srgb ? "1" : "0"}};
}

std::string fullscreen_vertex_source() {
  // Vertex ids 0, 1, 2 -> (-1,-1), (3,-1), (-1,3): one triangle whose
  // clipped part is exactly the viewport, so no diagonal seam and no buffers.
  return "#version 450 core\n"
         "void main() {\n"
         "  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;\n"
         "  gl_Position = vec4(p, 0.0, 1.0);\n"
         "}\n";
}

}  // namespace ms
