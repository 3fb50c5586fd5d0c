#include <string>

#include "core/error.h"
#include "scene/graph_build.h"
#include "scene/toml_read.h"

// [scene.graph]: the TOML table turned into the JSON document a graph file
// gives, so one builder reads both and names the same pointers.
namespace ms {

namespace {

// A TOML value as JSON values under `parent` (toml++ nests at most 256
// deep, so recursion is bounded here).
void add_toml(JsonDoc& doc, const toml::node& n, int parent, std::string_view key, int& last) {
  JsonValue v;
  v.line = static_cast<int>(n.source().begin.line);
  v.parent = parent;
  doc.set_key(v, key);
  if (parent != -1) v.index = doc.values[static_cast<std::size_t>(parent)].count++;
  if (const auto* x = n.as_floating_point()) v.kind = JsonKind::number, v.number = x->get();
  else if (const auto* i = n.as_integer()) v.kind = JsonKind::number, v.number = static_cast<double>(i->get());
  else if (const auto* s = n.as_string()) v.kind = JsonKind::string, doc.set_text(v, s->get());
  else if (const auto* b = n.as_boolean()) v.kind = JsonKind::boolean, v.number = b->get() ? 1 : 0;
  else if (n.is_array()) v.kind = JsonKind::array;
  else if (n.is_table()) v.kind = JsonKind::object;
  else v.kind = JsonKind::null;  // dates and times: refused where a number or name is due
  const int id = static_cast<int>(doc.values.size());
  if (parent != -1) {
    if (last == -1) doc.values[static_cast<std::size_t>(parent)].first = id;
    else doc.values[static_cast<std::size_t>(last)].next = id;
    last = id;
  }
  doc.values.push_back(v);
  int child_last = -1;
  if (const auto* a = n.as_array())
    for (const toml::node& e : *a) add_toml(doc, e, id, {}, child_last);
  if (const auto* t = n.as_table())
    for (auto&& [k, e] : *t) add_toml(doc, e, id, k.str(), child_last);
}

}  // namespace

SceneGraph load_graph_table(const toml::table& graph, const std::string& display, std::vector<Material>& materials) {
  JsonDoc doc;
  int last = -1;
  add_toml(doc, graph, -1, {}, last);
  for (int c = doc.at(0).first; c != -1; c = doc.at(c).next)
    if (doc.key(c) != "root")
      fail_input("unknown key " + quote(doc.key(c)), display, doc.at(c).line, "scene.graph" + doc.pointer(c),
                 "[scene.graph] holds only root, as a graph file does");
  const int root = doc.member(0, "root");
  if (root == -1)
    fail_input("missing 'root'", display, doc.at(0).line, "scene.graph", "[scene.graph.root] is the root node");
  if (materials.empty()) materials = graph_default_materials(doc, display, "scene.graph");
  return build_graph(doc, root, display, "scene.graph", materials);
}

}  // namespace ms
