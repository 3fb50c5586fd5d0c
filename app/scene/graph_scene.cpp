#include "scene/graph_scene.h"

#include <algorithm>
#include <cmath>
#include <system_error>

#include <glm/geometric.hpp>
#include <glm/common.hpp>

#include "core/format.h"
#include "io/input_file.h"
#include "io/path_roots.h"
#include "scene/graph_build.h"

namespace ms {

namespace fs = std::filesystem;

Bounds graph_bounds(const GraphBox& box) {
  const float pad = static_cast<float>(1e-3 * glm::length(glm::dvec3(box.max - box.min)) + 1e-3);  // no float overflow
  Bounds b;
  b.kind = BoundsKind::box;
  b.min = box.min - pad;
  b.max = box.max + pad;
  return b;
}

namespace {

// Judged before the file is looked at, so the error does not tell which
// files exist out there, and with the include rule (map, shadertoy).
void confine_graph(const Reader& r, int line, const fs::path& file, const fs::path& scene_file,
                   std::vector<fs::path> roots) {
  std::error_code ec;
  roots.insert(roots.begin(), fs::absolute(scene_file, ec).parent_path());
  if (within_roots(file, roots)) return;
  r.fail(line, "scene.graph",
         "the graph file " + quote(ms::display_path(fs::absolute(file, ec))) +
             " is outside the directories includes may read",
         "allowed: " + describe_roots(roots) + "; widen with --allow-include DIR");
}

}  // namespace

void attach_graph(const Reader& r, const toml::table& t, const fs::path& display_path,
                  const std::vector<fs::path>& roots, Scene& scene) {
  const toml::node* n = t.get("graph");
  SceneGraph g;
  if (const toml::table* inline_graph = n->as_table()) {
    g = load_graph_table(*inline_graph, r.file(), scene.materials);
    g.file = display_path;
  } else {
    std::string file;
    r.read(t, "scene", "graph", file);
    const int line = Reader::line_of(t, "graph");
    if (file.empty()) r.fail(line, "scene.graph", "'scene.graph' must not be empty");
    const fs::path resolved = (display_path.parent_path() / fs::path(file)).lexically_normal();
    confine_graph(r, line, resolved, display_path, roots);
    if (const std::string why = input_file_problem(resolved); !why.empty())
      r.fail(line, "scene.graph", "graph file " + quote(resolved.string()) + " " + why,
             why == "not found" ? "'scene.graph' is relative to the scene file" : "");
    g = load_graph_file(resolved, scene.materials);
  }
  const GraphNode& root = g.root_node();
  scene.bounds_declared = scene.bounds.kind != BoundsKind::none;
  if (!scene.bounds_declared) scene.bounds = graph_bounds(root.box);
  Quality& q = scene.quality;
  if (std::find(q.explicit_keys.begin(), q.explicit_keys.end(), "lipschitz") == q.explicit_keys.end()) {
    q.lipschitz = root.lipschitz;
    q.lipschitz_derived = true;
  }
  scene.graph = std::make_shared<const SceneGraph>(std::move(g));
}

std::string graph_overhang(const Scene& scene) {
  if (!scene.graph || !scene.bounds_declared) return {};
  const GraphBox& g = scene.graph->root_node().box;
  const Bounds& b = scene.bounds;
  std::string out;
  const auto add = [&](float by, const char* dir) {
    if (by > 0.0f) out += (out.empty() ? "by " : ", ") + printf_number("%.4g", by) + " along " + dir;
  };
  if (b.kind == BoundsKind::box) {
    const char* axes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      add(g.max[i] - b.max[i], (std::string("+") + axes[i]).c_str());
      add(b.min[i] - g.min[i], (std::string("-") + axes[i]).c_str());
    }
  }
  return out;
}

namespace {

std::string vec3_text(glm::vec3 v) {
  return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
}

}  // namespace

std::vector<std::string> scene_summary(const Scene& scene) {
  std::vector<std::string> out;
  const auto source = [&]() -> std::string {
    if (scene.graph) return "graph " + scene.graph->file.string();
    if (!scene.map_file.empty()) return "map " + scene.map_file.string();
    if (!scene.shadertoy_file.empty()) return "shadertoy " + scene.shadertoy_file.string();
    return "passes";
  };
  out.push_back("scene: " + (scene.name.empty() ? scene.file.stem().string() : scene.name) + ", " + source());
  if (scene.graph) {
    const SceneGraph& g = *scene.graph;
    const GraphNode& root = g.root_node();
    std::size_t modifiers = 0;
    for (const GraphNode& n : g.nodes) modifiers += n.unary;
    const std::size_t binary = g.nodes.size() - static_cast<std::size_t>(g.primitives) - modifiers;
    out.push_back("  graph: " + std::to_string(g.primitives) + " primitives, " + std::to_string(g.operators) +
                  " operators (" + std::to_string(binary) + " binary, " + std::to_string(modifiers) +
                  " modifiers), box " + vec3_text(root.box.min) + " to " + vec3_text(root.box.max) +
                  ", Lipschitz bound " + format_number(root.lipschitz));
  }
  if (scene.graph_alone) {
    const Plane& floor = scene.planes.back();
    out.push_back("  defaults: camera at " + vec3_text(scene.camera.position) + " looking at " +
                  vec3_text(scene.camera.target) + ", " + std::to_string(scene.lights.size()) +
                  " lights, floor at y = " + format_number(-floor.offset) + ", " +
                  std::to_string(scene.materials.size() - 1) + " materials besides the floor's");
  }
  const Bounds& b = scene.bounds;
  const std::string from = scene.graph && !scene.bounds_declared ? " (the graph's box)" : "";
  if (b.kind == BoundsKind::box) out.push_back("  bounds: box " + vec3_text(b.min) + " to " + vec3_text(b.max) + from);
  else if (b.kind == BoundsKind::sphere)
    out.push_back("  bounds: sphere at " + vec3_text(b.center) + ", radius " + format_number(b.radius));
  else out.push_back("  bounds: none");
  out.push_back("  lipschitz: " + format_number(scene.quality.lipschitz) +
                (scene.quality.lipschitz_derived ? " (the graph's bound)" : ""));
  return out;
}

}  // namespace ms
