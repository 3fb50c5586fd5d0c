// A scene file's [scene] graph: a JSON file's name or an inline table,
// read into Scene::graph, and what follows from it (docs/scene-graph.md):
// without a [bounds] table the scene's bounds are the graph's box, and
// without an explicit [quality] lipschitz its factor is the graph's bound.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "scene/scene.h"
#include "scene/toml_read.h"

namespace ms {

// `t` is the [scene] table; materials are read already. A graph file must
// lie, where its symlinks lead, in the scene file's folder or `roots`.
void attach_graph(const Reader& r, const toml::table& t, const std::filesystem::path& display_path,
                  const std::vector<std::filesystem::path>& roots, Scene& scene);

// The box the tracer marches for a graph with no [bounds]: the graph's,
// grown so that a hit's tolerance and the normals' offsets near the
// surface stay inside.
Bounds graph_bounds(const GraphBox& box);

// Where the graph's box pokes out of the scene's declared [bounds] box: ""
// when it does not, else "by 0.3 along +x, 0.1 along -y". For the warning
// that says what would be cut off (a sphere is probed like a map's).
std::string graph_overhang(const Scene& scene);

// `info SCENE.toml`'s lines for a scene: its source, and for a graph its
// counts, its box and its Lipschitz bound, and the bounds and factor used.
std::vector<std::string> scene_summary(const Scene& scene);

}  // namespace ms
