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
// the builder keeps per value and level (io/json_doc.h's JsonCost).
SceneGraph load_graph_file(const std::filesystem::path& file, const std::vector<Material>& materials);

// [scene.graph] of a scene file, holding `root` as the file would.
SceneGraph load_graph_table(const toml::table& graph, const std::string& display,
                            const std::vector<Material>& materials);

}  // namespace ms
