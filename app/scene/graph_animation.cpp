#include "scene/graph_animation.h"

#include <regex>

#include "core/error.h"
#include "core/format.h"
#include "io/input_file.h"
#include "scene/animation.h"
#include "scene/graph_build.h"
#include "scene/graph_scene.h"
#include "core/suggest.h"

namespace ms {
namespace {

// The graph's document, read again from its file: a static graph keeps
// none, so only an animated one pays for it.
std::shared_ptr<const GraphDoc> read_graph_doc(const SceneGraph& g) {
  auto d = std::make_shared<GraphDoc>();
  d->display = g.file.string();
  d->doc = parse_json_doc(read_input_file(g.file, "graph file"), d->display);
  d->root = d->doc.member(0, "root");
  return d;
}

bool is_number(const JsonDoc& doc, int v) { return v != -1 && doc.at(v).kind == JsonKind::number; }

// The numbers of array `v` when it holds exactly `n` of them, else {}.
std::vector<int> numbers_of(const JsonDoc& doc, int v, int n) {
  std::vector<int> out;
  if (v == -1 || doc.at(v).kind != JsonKind::array || doc.at(v).count != n) return {};
  for (int c = doc.at(v).first; c != -1; c = doc.at(c).next) {
    if (!is_number(doc, c)) return {};
    out.push_back(c);
  }
  return out;
}

// The node objects whose "name" is `name`; every name, for a did-you-mean.
std::vector<int> nodes_named(const JsonDoc& doc, std::string_view name, std::vector<std::string>& names) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(doc.values.size()); ++i) {
    if (doc.at(i).kind != JsonKind::string || doc.key(i) != "name") continue;
    const int parent = doc.at(i).parent;
    if (parent == -1 || doc.at(parent).kind != JsonKind::object) continue;
    names.emplace_back(doc.text(i));
    if (doc.text(i) == name) out.push_back(parent);
  }
  return out;
}

// The numbers key `key` of node `node` animates, or an error.
GraphSlot key_slot(const JsonDoc& doc, int node, const std::string& key, const std::string& object) {
  GraphSlot s;
  const int v = doc.member(node, key);
  if (key == "rotate") {
    const std::vector<int> r = numbers_of(doc, v, 4);
    if (!r.empty()) s.values = {r[3]};  // the angle; a track has 1 or 3 values
  } else if (key == "translate") {
    s.values = numbers_of(doc, v, 3);
  } else if (is_number(doc, v)) {
    s.values = {v};
  } else if (key != "name" && key != "sdf" && key != "op" && key != "material") {
    s.values = numbers_of(doc, v, 3);
  }
  if (!s.values.empty()) return s;
  std::vector<std::string> keys;
  for (int c = doc.at(node).first; c != -1; c = doc.at(c).next) {
    const std::string k(doc.key(c));
    if (k == "rotate" || k == "translate" || is_number(doc, c) || numbers_of(doc, c, 3).size() == 3) keys.push_back(k);
  }
  const std::vector<std::string_view> views(keys.begin(), keys.end());
  if (v == -1) {
    s.error = object + " has no " + quote(key) + " to animate";
    s.hint = did_you_mean(key, views);
    if (s.hint.empty() && (key == "translate" || key == "rotate" || key == "scale"))
      s.hint = "give the node a " + key + " in the graph file: a track moves the value the file sets";
  } else {
    s.error = quote(key) + " of " + object + " cannot be animated";
    s.hint = "a track sets a number, a vec3, translate, scale or rotate's angle";
  }
  if (s.hint.empty() && !keys.empty()) {
    s.hint = "animatable: ";
    for (std::size_t i = 0; i < keys.size(); ++i) s.hint.append(i ? ", " : "").append(keys[i]);
  }
  return s;
}

}  // namespace

bool is_graph_target(const std::string& target) { return target.rfind("graph.", 0) == 0; }

GraphSlot find_graph_slot(const std::string& target, Scene& scene) {
  GraphSlot s;
  static const std::regex form(R"(^graph\.([^.]{1,64})\.([A-Za-z_][A-Za-z0-9_]{0,31})$)");
  std::smatch m;
  if (target.size() > 128 || !std::regex_match(target, m, form)) {
    s.error = "unknown animation target " + quote(target);
    s.hint = "a graph node's value is graph.<node name>.<key>, e.g. graph.gear.translate";
    return s;
  }
  if (!scene.graph) {
    s.error = quote(target) + " names a graph node, but the scene has no graph";
    return s;
  }
  if (scene.graph->file.extension() != ".json") {
    s.error = quote(target) + ": an inline [scene.graph] cannot be animated";
    s.hint = "move the graph to a .json file ([scene] graph = \"NAME.json\")";
    return s;
  }
  if (!scene.graph_doc) scene.graph_doc = read_graph_doc(*scene.graph);
  const JsonDoc& doc = scene.graph_doc->doc;
  std::vector<std::string> names;
  const std::vector<int> nodes = nodes_named(doc, m[1].str(), names);
  if (nodes.size() != 1) {
    const std::vector<std::string_view> views(names.begin(), names.end());
    s.error = nodes.empty() ? "no graph node is named " + quote(m[1].str())
                            : std::to_string(nodes.size()) + " graph nodes are named " + quote(m[1].str());
    s.hint = nodes.empty() ? did_you_mean(m[1].str(), views) : "give the node to animate a name of its own";
    if (s.hint.empty()) s.hint = "a node is named by its \"name\" key in " + scene.graph_doc->display;
    return s;
  }
  return key_slot(doc, nodes[0], m[2].str(), "graph node " + quote(m[1].str()));
}

void pose_graph(Scene& scene, const std::vector<std::pair<const AnimationTrack*, std::array<double, 3>>>& values) {
  if (values.empty() || !scene.graph_doc) return;
  JsonDoc doc = scene.graph_doc->doc;
  for (const auto& [track, v] : values)
    for (std::size_t i = 0; i < track->graph_values.size(); ++i)
      doc.values[static_cast<std::size_t>(track->graph_values[i])].number = v[i];
  SceneGraph g = build_graph(doc, scene.graph_doc->root, scene.graph_doc->display, "", scene.materials);
  g.file = scene.graph->file;
  if (!scene.bounds_declared) scene.bounds = graph_bounds(g.root_node().box);
  if (scene.quality.lipschitz_derived) scene.quality.lipschitz = g.root_node().lipschitz;
  scene.graph = std::make_shared<const SceneGraph>(std::move(g));
}

bool animates_graph(const Scene& scene) {
  for (const AnimationTrack& tr : scene.animation)
    if (!tr.graph_values.empty()) return true;
  return false;
}

void pose_graph_at(Scene& scene, double time) {
  std::vector<std::pair<const AnimationTrack*, std::array<double, 3>>> values;
  for (const AnimationTrack& tr : scene.animation)
    if (!tr.graph_values.empty()) values.emplace_back(&tr, evaluate(tr, time));
  pose_graph(scene, values);
}

}  // namespace ms
