// The pruning pass's compute shader: per grid cell, the instructions of
// the nodes that can change the field there (docs/scene-graph.md).
#include <set>

#include "scene/graph_unary.h"
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

// msGraphRegion: where modifier fn's child is evaluated for the points
// within r of c (c in the modifier's frame; its begin instruction at k,
// unit instructions to its end): the ball (c2, r2), or false
// where the pass keeps the modifier whole (GraphUnary::inside).
std::string region_glsl(const SceneGraph& g) {
  std::set<int> unaries;
  for (const GraphNode& n : g.nodes)
    if (n.unary) unaries.insert(n.fn);
  if (unaries.empty()) return {};
  std::string s =
      "vec3 msRepeatRegion(vec3 c, float r, uint k, uint unit, vec3 spacing, vec3 count, vec3 lo, vec3 hi, "
      "float slack, out float r2);\n"
      "bool msGraphRegion(uint fn, uint o, vec3 c, float r, uint k, uint unit, out vec3 c2, out float r2) {\n"
      "  float n;\n  r2 = r;\n  c2 = c;\n  switch (fn) {\n";
  for (int fn : unaries) {
    const GraphUnary& u = graph_unaries()[static_cast<std::size_t>(fn)];
    const std::string c = "    case " + std::to_string(fn) + "u: ";
    if (u.inside == GraphUnary::Inside::point) s += c + "c2 = msGraphBegin(fn, o, c, 0.0, n); return true;\n";
    if (u.inside == GraphUnary::Inside::copies)
      s += c + "c2 = msRepeatRegion(c, r, k, unit" + buffer_args(u.params) + ", r2); return true;\n";
  }
  return s + "  }\n  return false;\n}\n";
}

}  // namespace

std::string graph_prune_source(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b) {
  return "#define MS_COUNT_PRIMS(n)\n#define MS_GRAPH_PRUNING 1\n" + defines(g, plan, b, 1) +
         "#include \"graph_buffers.glsl\"\n" + dispatch_glsl(g) + "#include \"graph_interp.glsl\"\n" +
         prune_rules_glsl(g) + region_glsl(g) + "#include \"graph_prune.glsl\"\n";
}

}  // namespace ms
