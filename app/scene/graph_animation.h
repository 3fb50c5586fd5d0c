// [[animation]] of a scene graph's nodes (docs/scene-graph.md#animation):
// a target "graph.NAME.KEY" names a node of a graph file by its "name" and
// one of its numbers: translate (x, y, z), scale, rotate (the angle in
// degrees; the axis stays the file's) or a parameter of its function (a
// number, or a vec3). The values live in the graph's parsed JSON; each
// frame sets them in a copy and rebuilds the graph from it, with its box,
// bounds and Lipschitz bound, exactly as the loader builds a static one.
//
//   GraphSlot s = find_graph_slot("graph.gear.translate", scene);  // error/hint on failure
//   pose_graph_at(scene, time);                                   // animated() calls it
#pragma once
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/json_doc.h"
#include "scene/scene.h"

namespace ms {

// A graph file's parsed document, kept for an animated graph (Scene::graph_doc).
struct GraphDoc {
  JsonDoc doc;
  int root = -1;        // the value of "root"
  std::string display;  // the file, as errors name it
};

// A resolved graph target: the document's numbers it sets (1 or 3), or why
// it cannot be animated (error, hint).
struct GraphSlot {
  std::vector<int> values;
  std::string error, hint;
  int arity() const { return static_cast<int>(values.size()); }
};

bool is_graph_target(const std::string& target);

// Resolves `target` on scene.graph, reading its file into scene.graph_doc
// the first time. Unknown or repeated names and keys are errors with a
// did-you-mean.
GraphSlot find_graph_slot(const std::string& target, Scene& scene);

// `scene`'s graph rebuilt with each track's value set (tracks of graph
// targets only), and what follows from it: without [bounds] the bounds are
// the new box, a derived Lipschitz factor the new bound. Throws bad_input
// naming the graph file and the JSON pointer when a value breaks the graph
// (a scale of 0, a negative radius), as the loader would.
void pose_graph(Scene& scene, const std::vector<std::pair<const AnimationTrack*, std::array<double, 3>>>& values);

// Whether a track of `scene` moves a graph node.
bool animates_graph(const Scene& scene);

// pose_graph() with the graph tracks' values at `time`: only the graph
// moves (the camera, lights and the rest are animated()'s).
void pose_graph_at(Scene& scene, double time);

}  // namespace ms
