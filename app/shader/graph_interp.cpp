#include "shader/graph_interp.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "scene/graph_vocab.h"
#include "shader/assemble.h"
#include "shader/graph_glsl.h"

namespace ms {

namespace {

// The pruning pass's two levels: coarse cells of kSplit^3 fine ones, each
// keeping up to kCoarseList instructions.
constexpr int kSplit = 4;
constexpr std::size_t kCoarseList = 2048;
constexpr int kPruneLoopLimit = 65000;

glm::ivec3 coarse_dims(const GraphEvalPlan& plan) { return (plan.dims + kSplit - 1) / kSplit; }
// Where the fine cells' lists start in the program buffer.
std::size_t fine_base(const GraphEvalPlan& plan, const GraphBuffers& b) {
  return b.program.size() + coarse_cell_count(plan) * kCoarseList;
}

constexpr std::uint32_t kLeaf = 0x80000000u, kSwap = 0x40000000u, kIndex = 0x3FFFFFFFu;

std::uint32_t bits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// Postfix with the child needing the deeper stack first (Sethi-Ullman), so
// a chain nested 100,000 deep needs a stack of 2; returns the depth.
int emit_program(const SceneGraph& g, std::vector<std::uint32_t>& out) {
  std::vector<int> need(g.nodes.size(), 1);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const GraphNode& n = g.nodes[i];
    if (n.leaf) continue;
    const int l = need[static_cast<std::size_t>(n.left)], r = need[static_cast<std::size_t>(n.right)];
    need[i] = l == r ? l + 1 : std::max(l, r);
  }
  struct Item { int node; bool expanded; };
  std::vector<Item> stack{{g.root, false}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    const GraphNode& n = g.nodes[static_cast<std::size_t>(it.node)];
    if (n.leaf) {
      out.push_back(kLeaf | static_cast<std::uint32_t>(it.node));
      continue;
    }
    const bool right_first = need[static_cast<std::size_t>(n.right)] > need[static_cast<std::size_t>(n.left)];
    if (it.expanded) {
      out.push_back(static_cast<std::uint32_t>(it.node) | (right_first ? kSwap : 0u));
      continue;
    }
    stack.push_back({it.node, true});
    // Pushed last, run first.
    stack.push_back({right_first ? n.left : n.right, false});
    stack.push_back({right_first ? n.right : n.left, false});
  }
  return need[static_cast<std::size_t>(g.root)];
}

std::string buffers_glsl(bool writable) {
  const std::string coarse =
      writable ? "layout(std430, binding = 7) buffer MsGraphCoarse { uvec4 msGraphCoarse[]; };\n" : "";
  const char* ro = writable ? "" : "readonly ";
  return std::string("layout(std430, binding = 3) readonly buffer MsGraphNodes { uvec4 msGraphNode[]; };\n") +
         "layout(std430, binding = 4) readonly buffer MsGraphFloats { float msGraphF[]; };\n" +
         "layout(std430, binding = 5) " + ro + "buffer MsGraphProgram { uint msGraphProg[]; };\n" +
         "layout(std430, binding = 6) " + ro + "buffer MsGraphCells { uvec4 msGraphCell[]; };\n" + coarse;
}

// msGraphPrim and msGraphOp: a case for each function the graph uses.
std::string dispatch_glsl(const SceneGraph& g) {
  std::set<int> prims, ops;
  for (const GraphNode& n : g.nodes) (n.leaf ? prims : ops).insert(n.fn);
  std::string s = "float msGraphPrim(uint fn, uint o, vec3 q) {\n  switch (fn) {\n";
  for (int fn : prims) {
    const GraphPrimitive& p = graph_primitives()[static_cast<std::size_t>(fn)];
    std::string args;
    int k = 0;
    for (const GraphParam& d : p.params) {
      std::string a = d.size == 1 ? "" : "vec" + std::to_string(d.size) + "(";
      for (int i = 0; i < d.size; ++i, ++k) a += (i ? ", " : "") + std::string("msGraphF[o + ") + std::to_string(k) + "u]";
      args += ", " + a + (d.size == 1 ? "" : ")");
    }
    s += "    case " + std::to_string(fn) + "u: return " + std::string(p.name) + "(q" + args + ");\n";
  }
  s += "  }\n  return 1e30;\n}\n";
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

// A leaf at world point p, and the program run from `start`.
constexpr const char* kRun = R"(vec2 msGraphLeaf(uint i, vec3 p) {
  uvec4 n = msGraphNode[i];
  uint o = n.y;
  vec3 q = vec3(dot(vec3(msGraphF[o], msGraphF[o + 1u], msGraphF[o + 2u]), p),
                dot(vec3(msGraphF[o + 3u], msGraphF[o + 4u], msGraphF[o + 5u]), p),
                dot(vec3(msGraphF[o + 6u], msGraphF[o + 7u], msGraphF[o + 8u]), p)) +
           vec3(msGraphF[o + 9u], msGraphF[o + 10u], msGraphF[o + 11u]);
  return vec2(msGraphPrim(n.x, o + 13u, q) * msGraphF[o + 12u], float(n.z));
}
vec2 msGraphNodeOp(uint i, vec2 a, vec2 b) {
  uvec4 n = msGraphNode[i];
  return msGraphOp(n.x, n.y, a, b);
}
)";

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
  if (plan.prune && !plan.keep_all) return 1;
  std::set<std::pair<bool, int>> kinds;
  for (const GraphNode& n : g.nodes) kinds.insert({n.leaf, n.fn});
  int cap = 8;
  while (cap > 1 && cap * static_cast<int>(kinds.size()) > 16) cap /= 2;
  int u = 1;
  while (u < cap && static_cast<double>(program) * 512.0 > 131070.0 * u) u *= 2;
  return u;
}

constexpr const char* kRunStep = R"(    if (k < end) {
      uint ins = msGraphProg[k];
      bool op = (ins & 0x80000000u) == 0u;
      if (!op) {
        st[sp++] = msGraphLeaf(ins & 0x3FFFFFFFu, p);
        MS_COUNT_PRIMS(1);
        ++k;
        ins = k < end ? msGraphProg[k] : 0x80000000u;
        op = (ins & 0x80000000u) == 0u;
      }
      if (op) {
        vec2 b = st[--sp];
        vec2 a = st[--sp];
        if ((ins & 0x40000000u) != 0u) { vec2 t = a; a = b; b = t; }
        st[sp++] = msGraphNodeOp(ins & 0x3FFFFFFFu, a, b);
        ++k;
      }
    }
)";

std::string run_glsl(int n) {
  std::string s = "vec2 msGraphRun(uint start, uint count, vec3 p) {\n  vec2 st[MS_GRAPH_STACK];\n  int sp = 0;\n";
  s += "  uint end = start + count;\n  for (uint k = start; k < end;) {\n";
  for (int j = 0; j < n; ++j) s += kRunStep;
  s += "  }\n  return st[0];\n}\n";
  return s;
}

std::string vec3_glsl(glm::vec3 v) {
  return "vec3(" + glsl_float(v.x) + ", " + glsl_float(v.y) + ", " + glsl_float(v.z) + ")";
}

std::string defines(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b) {
  std::string s = "#define MS_GRAPH_STACK " + std::to_string(std::max(b.stack, 1)) + "\n";
  s += "#define MS_GRAPH_LEN " + std::to_string(b.program.size()) + "u\n";
  s += "#define MS_GRAPH_L " + glsl_float(g.root_node().lipschitz) + "\n";
  if (plan.prune) {
    s += "#define MS_GRID_MIN " + vec3_glsl(plan.min) + "\n#define MS_GRID_CELL " + vec3_glsl(plan.cell) + "\n";
    s += "#define MS_GRID_DIM ivec3(" + std::to_string(plan.dims.x) + ", " + std::to_string(plan.dims.y) + ", " +
         std::to_string(plan.dims.z) + ")\n";
    s += "#define MS_GRID_LIST " + std::to_string(plan.list_max) + "u\n";
    const glm::ivec3 cd = coarse_dims(plan);
    s += "#define MS_GRID_SPLIT " + std::to_string(kSplit) + "\n#define MS_COARSE_DIM ivec3(" + std::to_string(cd.x) +
         ", " + std::to_string(cd.y) + ", " + std::to_string(cd.z) + ")\n";
    s += "#define MS_COARSE_LIST " + std::to_string(kCoarseList) + "u\n";
    s += "#define MS_FINE_BASE " + std::to_string(fine_base(plan, b)) + "u\n";
  }
  return s;
}

// Which child of operator fn may go on a cell where the children's fields
// lie in ia and ib (lo, hi): 1 drops b, 2 drops a, 0 keeps both. For an
// intersection the fields are negated, for a subtraction only a.
std::string prune_rules_glsl(const SceneGraph& g) {
  std::set<int> ops;
  for (const GraphNode& n : g.nodes)
    if (!n.leaf) ops.insert(n.fn);
  std::string s = "float msReach(uint fn, uint o, float AHI) {\n  float P0 = msGraphF[o];\n  switch (fn) {\n";
  for (int fn : ops) {
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(fn)];
    if (!op.reach.empty()) s += "    case " + std::to_string(fn) + "u: return " + std::string(op.reach) + ";\n";
  }
  s += "  }\n  return -1.0;\n}\n";
  s += "int msDrop(uint fn, uint o, vec2 ia, vec2 ib);\n";
  s += "int msGraphPrune(uint fn, uint o, vec2 ia, vec2 ib) {\n  switch (fn) {\n";
  for (int fn : ops) {
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(fn)];
    if (op.reach.empty()) continue;
    const std::string c = "    case " + std::to_string(fn) + "u: ";
    if (op.family == OpFamily::union_) s += c + "return msDrop(fn, o, ia, ib);\n";
    else if (op.family == OpFamily::intersection) s += c + "return msDrop(fn, o, -ia.yx, -ib.yx);\n";
    else if (op.family == OpFamily::subtraction) s += c + "return msDrop(fn, o, -ia.yx, ib) == 1 ? 1 : 0;\n";
  }
  s += "  }\n  return 0;\n}\n";
  return s;
}

// The pruning pass: one invocation a cell walks the whole program at the
// cell's centre, keeping an interval per stack entry (value -+ L r) and
// the cell's list so far; a dropped child's instructions are cut out.
constexpr const char* kPrune = R"(int msDrop(uint fn, uint o, vec2 ia, vec2 ib) {
  float rb = msReach(fn, o, ia.y), ra = msReach(fn, o, ib.y);
  if (rb >= 0.0 && ib.x >= ia.y + rb) return 1;
  if (ra >= 0.0 && ia.x >= ib.y + ra) return 2;
  return 0;
}
struct MsEntry { vec2 v; float lo, hi; uint start, count; };
layout(local_size_x = 64) in;
// Level 0 prunes the whole program per coarse cell; level 1 prunes its
// coarse cell's list per fine cell (MS_GRID_SPLIT^3 of them a coarse cell).
uniform int uLevel;
void main() {
  ivec3 dims = uLevel == 0 ? MS_COARSE_DIM : MS_GRID_DIM;
  uint cellIndex = gl_GlobalInvocationID.x;
  if (cellIndex >= uint(dims.x * dims.y * dims.z)) return;
  ivec3 c = ivec3(int(cellIndex) % dims.x, (int(cellIndex) / dims.x) % dims.y, int(cellIndex) / (dims.x * dims.y));
  vec3 size = uLevel == 0 ? MS_GRID_CELL * float(MS_GRID_SPLIT) : MS_GRID_CELL;
  vec3 centre = MS_GRID_MIN + (vec3(c) + 0.5) * size;
  // The half diagonal, a little over: a point the tracer files under this
  // cell may lie a rounding error outside it.
  float r = 0.5 * length(size) * 1.001 + 1e-6;
  uint inStart = 0u, inCount = MS_GRAPH_LEN, listMax = MS_COARSE_LIST;
  uint base = MS_GRAPH_LEN + cellIndex * MS_COARSE_LIST;
  if (uLevel == 1) {
    ivec3 pc = c / MS_GRID_SPLIT;
    uvec4 parent = msGraphCoarse[pc.x + MS_COARSE_DIM.x * (pc.y + MS_COARSE_DIM.y * pc.z)];
    inStart = parent.x;
    inCount = parent.y;
    listMax = MS_GRID_LIST;
    base = MS_FINE_BASE + cellIndex * MS_GRID_LIST;
  }
  MsEntry st[MS_GRAPH_STACK];
  int sp = 0;
  uint len = 0u;
  bool overflow = false;
  for (uint k = inStart; k < inStart + inCount; ++k) {
    uint ins = msGraphProg[k];
    uint i = ins & 0x3FFFFFFFu;
    float L = uintBitsToFloat(msGraphNode[i].w);
    if ((ins & 0x80000000u) != 0u) {
      vec2 v = msGraphLeaf(i, centre);
      st[sp++] = MsEntry(v, v.x - L * r, v.x + L * r, len, 1u);
      if (len < listMax) msGraphProg[base + len] = ins; else overflow = true;
      ++len;
      continue;
    }
    MsEntry y = st[--sp];
    MsEntry x = st[--sp];  // x ran first
    bool swap = (ins & 0x40000000u) != 0u;
    MsEntry a = swap ? y : x, b = swap ? x : y;
    vec2 v = msGraphNodeOp(i, a.v, b.v);
    uvec4 n = msGraphNode[i];
    int drop = msGraphPrune(n.x, n.y, vec2(a.lo, a.hi), vec2(b.lo, b.hi));
    MsEntry res = MsEntry(v, v.x - L * r, v.x + L * r, x.start, 0u);
    if (drop == 0) {
      if (len < listMax) msGraphProg[base + len] = ins; else overflow = true;
      ++len;
      res.count = x.count + y.count + 1u;
    } else {
      MsEntry keep = drop == 1 ? a : b;
      // Keep y's instructions in x's place when x goes.
      if (keep.start != x.start && !overflow)
        for (uint j = 0u; j < keep.count; ++j) msGraphProg[base + x.start + j] = msGraphProg[base + keep.start + j];
      res.count = keep.count;
      len = x.start + keep.count;
    }
    st[sp++] = res;
  }
  uvec4 cell = uvec4(base, len, 0u, 0u);
  if (overflow) cell = uvec4(inStart, inCount, 0u, 1u);  // the input list, unpruned here
  if (uLevel == 0) msGraphCoarse[cellIndex] = cell; else msGraphCell[cellIndex] = cell;
}
)";

}  // namespace

std::size_t coarse_cell_count(const GraphEvalPlan& plan) {
  const glm::ivec3 d = coarse_dims(plan);
  return static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) * static_cast<std::size_t>(d.z);
}

std::size_t program_capacity(const GraphEvalPlan& plan, const GraphBuffers& b) {
  if (!plan.prune || plan.keep_all) return b.program.size();
  return fine_base(plan, b) + cell_count(plan) * static_cast<std::size_t>(plan.list_max);
}

std::size_t cell_count(const GraphEvalPlan& plan) {
  return static_cast<std::size_t>(plan.dims.x) * static_cast<std::size_t>(plan.dims.y) *
         static_cast<std::size_t>(plan.dims.z);
}

GraphEvalPlan plan_graph_eval(const SceneGraph& g, GraphEval eval, bool prune, const GraphBox& box, float cell_size) {
  GraphEvalPlan plan;
  plan.interpret = eval == GraphEval::interpreter || (eval == GraphEval::auto_ && g.primitives >= kInterpretFrom);
  // A coarse cell walks the whole program in one loop, which llvmpipe
  // would cut short past 65,535 iterations.
  // Only graphs whose every combinator has a pruning rule: with columns,
  // stairs, pipe, engrave, groove or tongue anywhere, random graphs gave
  // pruned images that differed from the whole graph's in about 1% of
  // their pixels (docs/scene-graph.md), so those graphs run unpruned.
  bool rules = true;
  for (const GraphNode& n : g.nodes)
    rules = rules && (n.leaf || !graph_operators()[static_cast<std::size_t>(n.fn)].reach.empty());
  plan.prune = plan.interpret && rules && box.finite() && !box.empty() && 2 * g.primitives < kPruneLoopLimit;
  // --no-prune keeps the grid, each cell holding the whole program: the
  // same shader, so the reference differs from the pruned field only by
  // what pruning drops (nothing, when it is exact), not by how a compiler
  // happened to round two different programs.
  plan.keep_all = !prune;
  if (!plan.prune) return plan;
  // A point outside the grid (a soft shadow marching through the
  // penumbra's reach around the bounds) runs the whole program.
  const glm::vec3 lo = box.min;
  const glm::vec3 extent = glm::max(box.max - box.min, glm::vec3(1e-4f));
  // About 32 fine cells a primitive, within 16^3 and 2^17: a fine cell
  // prunes its coarse cell's list, a coarse cell the whole program.
  const double target = std::clamp(32.0 * g.primitives, 4096.0, 131072.0);
  const float side = cell_size > 0.0f ? cell_size
                                      : static_cast<float>(std::cbrt(double(extent.x) * extent.y * extent.z / target));
  plan.dims = glm::clamp(glm::ivec3(glm::ceil(extent / side)), glm::ivec3(1), glm::ivec3(256));
  plan.cell = extent / glm::vec3(plan.dims);
  plan.min = lo;
  plan.list_max = 256;
  return plan;
}

GraphBuffers graph_buffers(const SceneGraph& g, const GraphEvalPlan&) {
  GraphBuffers b;
  for (const GraphNode& n : g.nodes) {
    const std::uint32_t offset = static_cast<std::uint32_t>(b.floats.size());
    if (n.leaf) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) b.floats.push_back(n.to_local[c][r]);
      b.floats.insert(b.floats.end(), {n.offset.x, n.offset.y, n.offset.z, n.scale});
    }
    const auto& defs = n.leaf ? graph_primitives()[static_cast<std::size_t>(n.fn)].params
                              : graph_operators()[static_cast<std::size_t>(n.fn)].params;
    const float* p = g.params.data() + n.param;
    b.floats.insert(b.floats.end(), p, p + param_floats(defs));
    b.nodes.insert(b.nodes.end(), {static_cast<std::uint32_t>(n.fn), offset, static_cast<std::uint32_t>(n.material),
                                   bits(n.lipschitz)});
  }
  b.stack = emit_program(g, b.program);
  return b;
}

std::string graph_map_interpreter(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b) {
  std::string s = "#include \"aov.glsl\"\n// map() interpreting the scene graph's node buffers: " +
                  std::to_string(g.primitives) + " primitives, " + std::to_string(g.operators) + " operators\n";
  s += defines(g, plan, b) + buffers_glsl(false) + dispatch_glsl(g) + kRun + run_glsl(copies(g, plan, b.program.size()));
  s += "vec2 map(vec3 p) {\n";
  if (plan.prune)
    s += R"(  vec3 g = (p - MS_GRID_MIN) / MS_GRID_CELL;
  if (all(greaterThanEqual(g, vec3(0.0))) && all(lessThan(g, vec3(MS_GRID_DIM)))) {
    ivec3 c = min(ivec3(g), MS_GRID_DIM - 1);
    uvec4 cell = msGraphCell[c.x + MS_GRID_DIM.x * (c.y + MS_GRID_DIM.y * c.z)];
    return msGraphRun(cell.x, cell.y, p);
  }
)";
  s += "  return msGraphRun(0u, MS_GRAPH_LEN, p);\n}\n";
  return s;
}

std::string graph_prune_source(const SceneGraph& g, const GraphEvalPlan& plan, const GraphBuffers& b) {
  return "#define MS_COUNT_PRIMS(n)\n" + defines(g, plan, b) + buffers_glsl(true) + dispatch_glsl(g) + kRun +
         prune_rules_glsl(g) + kPrune;
}

}  // namespace ms
