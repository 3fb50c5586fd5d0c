// The pruning pass's compute shader: per grid cell, the instructions of
// the nodes that can change the field there (docs/scene-graph.md).
#include <set>

#include "scene/graph_vocab.h"
#include "shader/graph_interp_detail.h"

namespace ms {

namespace {

using namespace graph_detail;

// Which child of operator fn may go on a cell where the children's fields
// lie in ia and ib (lo, hi): 1 drops b, 2 drops a, 0 keeps both. For an
// intersection the fields are negated, for a subtraction only a. An
// operator without a rule keeps both here, and only here.
std::string prune_rules_glsl(const SceneGraph& g) {
  std::set<int> ops;
  for (const GraphNode& n : g.nodes)
    if (n.binary()) ops.insert(n.fn);
  std::string s =
      "float msReach(uint fn, uint o, vec2 ia) {\n  float P0 = msGraphF[o], ALO = ia.x, AHI = ia.y;\n  switch (fn) {\n";
  for (int fn : ops) {
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(fn)];
    if (op.reach.empty()) continue;
    // P1 only where the operator has one: the last node's floats end the buffer.
    const std::string p1 = op.params.size() > 1 ? "float P1 = msGraphF[o + 1u]; " : "";
    s += "    case " + std::to_string(fn) + "u: { " + p1 + "return " + std::string(op.reach) + "; }\n";
  }
  s += "  }\n  return -1.0;\n}\n";
  s += "int msDrop(uint fn, uint o, vec2 ia, vec2 ib);\nint msCut(uint fn, uint o, vec2 ia, vec2 ib);\n";
  s += "int msGraphPrune(uint fn, uint o, vec2 ia, vec2 ib) {\n  switch (fn) {\n";
  for (int fn : ops) {
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(fn)];
    if (op.reach.empty()) continue;
    const std::string c = "    case " + std::to_string(fn) + "u: ";
    if (op.family == OpFamily::union_) s += c + "return msDrop(fn, o, ia, ib);\n";
    else if (op.family == OpFamily::intersection) s += c + "return msDrop(fn, o, -ia.yx, -ib.yx);\n";
    else if (op.family == OpFamily::subtraction) s += c + "return msDrop(fn, o, -ia.yx, ib) == 1 ? 1 : 0;\n";
    else s += c + "return msCut(fn, o, ia, ib);\n";
  }
  s += "  }\n  return 0;\n}\n";
  return s;
}

}  // namespace

std::string graph_prune_source(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b) {
  return "#define MS_COUNT_PRIMS(n)\n#define MS_GRAPH_PRUNING 1\n" + defines(g, plan, b, 1) +
         "#include \"graph_buffers.glsl\"\n" + dispatch_glsl(g) + "#include \"graph_interp.glsl\"\n" +
         prune_rules_glsl(g) + "#include \"graph_prune.glsl\"\n";
}

}  // namespace ms
