// Reads a scene graph (docs/scene-graph.md) from a parsed JSON document or
// from an inline [scene.graph] table, validating every node: an error names
// the file, the line and the JSON pointer, with a did-you-mean for names.
// Walks the tree with an explicit stack, so a chain nested 100,000 deep
// loads without recursion.
//
//   SceneGraph g = load_graph_file("molecule.json", scene.materials);
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "io/json_doc.h"
#include "scene/graph.h"
#include "scene/scene.h"

namespace ms {

// `node` is the value of the root node in `doc`; `prefix` goes before each
// JSON pointer in errors ("" for a file, "scene.graph" inline).
SceneGraph build_graph(const JsonDoc& doc, int node, const std::string& display, const std::string& prefix,
                       const std::vector<Material>& materials);

// A graph file: {"root": NODE}. Read within the memory budget with what
// the builder keeps per value and level (io/json_doc.h's JsonCost). Empty
// `materials` (a scene with no [[materials]]) are first filled with the
// defaults of the names the graph uses (graph_default_materials()).
SceneGraph load_graph_file(const std::filesystem::path& file, std::vector<Material>& materials);

// [scene.graph] of a scene file, holding `root` as the file would.
SceneGraph load_graph_table(const toml::table& graph, const std::string& display, std::vector<Material>& materials);

// The materials of a graph whose scene defines none: "default" (grey, for
// nodes that name no material), then one per name the graph uses, in order
// of first use, each its own colour. A name GLSL cannot take as MAT_<NAME>,
// two names GLSL sees as one, or too many are one line at the name.
std::vector<Material> graph_default_materials(const JsonDoc& doc, const std::string& display,
                                              const std::string& prefix);

}  // namespace ms
