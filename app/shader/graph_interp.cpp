#include "shader/graph_interp.h"

#include <algorithm>
#include <cstring>
#include <set>

#include "scene/graph_unary.h"
#include "scene/graph_vocab.h"
#include "shader/assemble.h"
#include "shader/graph_glsl.h"
#include "shader/graph_interp_detail.h"

namespace ms {

namespace graph_detail {
// Parameters read from the float buffer at o, as GLSL arguments.
std::string buffer_args(const std::vector<GraphParam>& params) {
  std::string args;
  int k = 0;
  for (const GraphParam& d : params) {
    const auto f = [](int i) { return "msGraphF[o + " + std::to_string(i) + "u]"; };
    if (d.points > 0) {  // a vertex list: its count, then a vec2 array
      args += ", " + f(k) + ", vec2[" + std::to_string(d.points) + "](";
      for (int i = 0; i < d.points; ++i)
        args += "vec2(" + f(k + 1 + 2 * i) + ", " + f(k + 2 + 2 * i) + (i + 1 < d.points ? "), " : "))");
      k += d.size;
      continue;
    }
    std::string a = d.size == 1 ? "" : "vec" + std::to_string(d.size) + "(";
    for (int i = 0; i < d.size; ++i, ++k) a += (i ? ", " : "") + std::string("msGraphF[o + ") + std::to_string(k) + "u]";
    args += ", " + a + (d.size == 1 ? "" : ")");
  }
  return args;
}

// msGraphBegin, msGraphEnd and msGraphFloor: each modifier's point map,
// value map and (repetitions) a copy's floor, at its parameters' offset o.
std::string modifier_dispatch_glsl(const std::set<int>& unaries) {
  std::string b = "vec3 msGraphBegin(uint fn, uint o, vec3 q, float t, out float n) {\n  n = 1.0;\n  switch (fn) {\n";
  std::string e = "float msGraphEnd(uint fn, uint o, float d, vec3 q) {\n  switch (fn) {\n";
  std::string f = "float msGraphFloor(uint fn, uint o, vec3 c) {\n  switch (fn) {\n";
  for (int fn : unaries) {
    const GraphUnary& u = graph_unaries()[static_cast<std::size_t>(fn)];
    const std::string c = "    case " + std::to_string(fn) + "u: ", args = buffer_args(u.params);
    if (!u.begin.empty()) b += c + "return " + std::string(u.begin) + "(q" + args + (u.copies ? ", t, n" : "") + ");\n";
    if (!u.end.empty())
      e += c + "return " + std::string(u.end) + "(d" + (u.end_point ? ", q" : "") + args + ");\n";
    if (u.copies) {
      const std::string at = std::to_string(param_floats(u.params) - kCopyFloorFloats);
      const auto fl = [&](int k) { return "msGraphF[o + " + at + "u + " + std::to_string(k) + "u]"; };
      f += c + "return opCopyFloor(c, vec3(" + fl(0) + ", " + fl(1) + ", " + fl(2) + "), vec3(" + fl(3) + ", " + fl(4) +
           ", " + fl(5) + "), " + fl(6) + ");\n";
    }
  }
  return b + "  }\n  return q;\n}\n" + e + "  }\n  return d;\n}\n" + f + "  }\n  return 0.0;\n}\n";
}

std::string dispatch_glsl(const SceneGraph& g) {
  std::set<int> prims, ops, unaries;
  for (const GraphNode& n : g.nodes) (n.leaf ? prims : n.unary ? unaries : ops).insert(n.fn);
  std::string s = "float msGraphPrim(uint fn, uint o, vec3 q) {\n  switch (fn) {\n";
  for (int fn : prims) {
    const GraphPrimitive& p = graph_primitives()[static_cast<std::size_t>(fn)];
    s += "    case " + std::to_string(fn) + "u: return " + std::string(p.name) + (p.dims == 2 ? "(q.xy" : "(q") +
         buffer_args(p.params) + ");\n";
  }
  s += "  }\n  return 1e30;\n}\n";
  if (!unaries.empty()) s += modifier_dispatch_glsl(unaries);
  s += "vec2 msGraphOp(uint fn, uint o, vec2 a, vec2 b) {\n  switch (fn) {\n";
  for (int fn : ops) {
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(fn)];
    std::vector<std::string> params;
    for (std::size_t i = 0; i < op.params.size(); ++i) params.push_back("msGraphF[o + " + std::to_string(i) + "u]");
    s += "    case " + std::to_string(fn) + "u: return " + graph_op_expr(fn, "a", "b", params.data()) + ";\n";
  }
  s += "  }\n  return a;\n}\n";
  return s;
}


std::string defines(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b, int copies) {
  std::string s = "#define MS_GRAPH_COPIES " + std::to_string(copies) + "\n#define MS_GRAPH_STACK " + std::to_string(std::max(b.stack, 1)) + "\n";
  s += "#define MS_GRAPH_FRAMES " + std::to_string(b.frames) + "\n#define MS_INDEX 0x0FFFFFFFu\n";
  s += "#define MS_GRAPH_LEN " + std::to_string(b.program.size()) + "u\n";
  s += "#define MS_GRAPH_L " + glsl_float(g.root_node().lipschitz) + "\n";
  // Only what the graph's structure fixes: where the grid lies is in the
  // cell buffer's head (grid_header()), so moving the graph recompiles nothing.
  if (plan.prune) {
    s += "#define MS_GRID_LEVELS " + std::to_string(kGridLevels) + "\n#define MS_GRID_HEADER " +
         std::to_string(kHeader) + "u\n#define MS_GRID_SPLIT " + std::to_string(kSplit) + "\n";
    s += "#define MS_GRID_LIST " + std::to_string(plan.list_max) + "u\n#define MS_COARSE_LIST " +
         std::to_string(kCoarseList) + "u\n";
  }
  return s;
}

}  // namespace graph_detail

namespace {

using namespace graph_detail;

// An instruction: a leaf, or a combinator (its children swapped when the
// right one ran first), a modifier's begin or its end; the node's index
// below.
constexpr std::uint32_t kLeaf = 0x80000000u, kSwap = 0x40000000u, kBegin = 0x20000000u, kEnd = 0x10000000u;

std::uint32_t bits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// Postfix with the child needing the deeper stack first (Sethi-Ullman), so
// a chain nested 100,000 deep needs a stack of 2; a modifier's child
// between its begin and end instructions. Returns the stack depth; fills
// each modifier's unit (begin to end, in instructions) and the deepest
// nesting of modifiers.
int emit_program(const SceneGraph& g, std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& unit, int& frames) {
  std::vector<int> need(g.nodes.size(), 1), depth(g.nodes.size(), 0);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const GraphNode& n = g.nodes[i];
    if (n.leaf) continue;
    const std::size_t l = static_cast<std::size_t>(n.left);
    if (n.unary) {
      need[i] = need[l];
      depth[i] = depth[l] + 1;
      continue;
    }
    const std::size_t r = static_cast<std::size_t>(n.right);
    need[i] = need[l] == need[r] ? need[l] + 1 : std::max(need[l], need[r]);
    depth[i] = std::max(depth[l], depth[r]);
  }
  frames = depth[static_cast<std::size_t>(g.root)];
  unit.assign(g.nodes.size(), 0u);
  std::vector<std::size_t> begun(g.nodes.size(), 0);
  struct Item { int node; bool expanded; };
  std::vector<Item> stack{{g.root, false}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    const GraphNode& n = g.nodes[static_cast<std::size_t>(it.node)];
    const std::uint32_t id = static_cast<std::uint32_t>(it.node);
    if (n.leaf) {
      out.push_back(kLeaf | id);
      continue;
    }
    if (n.unary) {
      if (it.expanded) {
        out.push_back(kEnd | id);
        unit[id] = static_cast<std::uint32_t>(out.size() - begun[id]);
        continue;
      }
      begun[id] = out.size();
      out.push_back(kBegin | id);
      stack.push_back({it.node, true});
      stack.push_back({n.left, false});
      continue;
    }
    const bool right_first = need[static_cast<std::size_t>(n.right)] > need[static_cast<std::size_t>(n.left)];
    if (it.expanded) {
      out.push_back(id | (right_first ? kSwap : 0u));
      continue;
    }
    stack.push_back({it.node, true});
    // Pushed last, run first.
    stack.push_back({right_first ? n.left : n.right, false});
    stack.push_back({right_first ? n.right : n.left, false});
  }
  return need[static_cast<std::size_t>(g.root)];
}

// llvmpipe ends a shader's loops after 65,535 iterations in all (one
// limiter shared by every loop of an invocation). A step runs a primitive
// and then, when the next instruction is an operator, that operator too
// (a union chain's program alternates them), so one copy a loop iteration
// lets a pixel run about 131,000 instructions over all its map() calls:
// plenty for pruned lists. Each copy multiplies the code LLVM compiles by
// every inlined map() call (16 copies of the plain loop took 75 s for one
// sphere kind, 1 copy 1.5 s), so only the unpruned runs, whose every call
// walks the whole program, get what 512 calls of it need, within 8 for
// one primitive and one combinator kind, fewer as the kinds grow.
int copies(const SceneGraph& g, const GraphEvalPlan& plan, std::size_t program) {
  if (plan.pruned()) return 1;
  std::set<std::pair<bool, int>> kinds;
  for (const GraphNode& n : g.nodes) kinds.insert({n.leaf, n.unary ? -1 - n.fn : n.fn});
  int cap = 8;
  while (cap > 1 && cap * static_cast<int>(kinds.size()) > 16) cap /= 2;
  int u = 1;
  while (u < cap && static_cast<double>(program) * 512.0 > 131070.0 * u) u *= 2;
  return u;
}

}  // namespace

GraphBuffers graph_buffers(const SceneGraph& g) {
  GraphBuffers b;
  std::vector<std::uint32_t> unit;
  b.stack = emit_program(g, b.program, unit, b.frames);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const GraphNode& n = g.nodes[i];
    const std::uint32_t offset = static_cast<std::uint32_t>(b.floats.size());
    if (!n.binary()) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) b.floats.push_back(n.to_local[c][r]);
      b.floats.insert(b.floats.end(), {n.offset.x, n.offset.y, n.offset.z, n.scale});
    }
    const auto& defs = n.leaf    ? graph_primitives()[static_cast<std::size_t>(n.fn)].params
                       : n.unary ? graph_unaries()[static_cast<std::size_t>(n.fn)].params
                                 : graph_operators()[static_cast<std::size_t>(n.fn)].params;
    const float* p = g.params.data() + n.param;
    b.floats.insert(b.floats.end(), p, p + param_floats(defs));
    // A modifier's third word is its unit's length (the pruning pass keeps
    // or drops it whole), a leaf's its material.
    const std::uint32_t third = n.unary ? unit[i] : static_cast<std::uint32_t>(n.material);
    b.nodes.insert(b.nodes.end(), {static_cast<std::uint32_t>(n.fn), offset, third, bits(n.lipschitz)});
  }
  return b;
}

std::string graph_map_interpreter(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b) {
  std::string s = "#include \"aov.glsl\"\n// map() interpreting the scene graph's node buffers: " +
                  std::to_string(g.primitives) + " primitives, " + std::to_string(g.operators) + " operators\n";
  return s + defines(g, plan, b, copies(g, plan, b.program.size())) + "#include \"graph_buffers.glsl\"\n" +
         dispatch_glsl(g) + "#include \"graph_interp.glsl\"\n";
}

}  // namespace ms
