#include "shader/graph_glsl.h"

#include <cmath>

#include "scene/graph_unary.h"
#include "scene/graph_vocab.h"
#include "shader/assemble.h"

namespace ms {

namespace {

std::string vec3_literal(glm::vec3 v) {
  return "vec3(" + glsl_float(v.x) + ", " + glsl_float(v.y) + ", " + glsl_float(v.z) + ")";
}

// The leaf's point: q = to_local * p + offset, written shortest for the
// common cases (a translation, a translation and a uniform scale).
std::string local_point(const GraphNode& n) {
  const glm::mat3& a = n.to_local;
  bool diagonal = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j && a[i][j] != 0.0f) diagonal = false;
  const bool uniform = diagonal && a[0][0] == a[1][1] && a[1][1] == a[2][2];
  std::string lin;
  if (uniform && a[0][0] == 1.0f) lin = "p";
  else if (uniform) lin = "p * " + glsl_float(a[0][0]);
  else {
    lin = "mat3(";
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) lin += glsl_float(a[c][r]) + (c == 2 && r == 2 ? ")" : ", ");
    lin += " * p";
  }
  if (n.offset == glm::vec3(0.0f)) return lin;
  return lin + " + " + vec3_literal(n.offset);
}

// Parameters as GLSL arguments: floats, vec2s, vec3s.
std::string leaf_args(const std::vector<GraphParam>& params, const float* p) {
  std::string out;
  for (const GraphParam& d : params) {
    if (d.points > 0) {  // a vertex list: its count, then a vec2 array
      out += ", " + glsl_float(p[0]) + ", vec2[" + std::to_string(d.points) + "](";
      for (int i = 0; i < d.points; ++i)
        out += "vec2(" + glsl_float(p[1 + 2 * i]) + ", " + glsl_float(p[2 + 2 * i]) + (i + 1 < d.points ? "), " : "))");
    } else if (d.size == 1) out += ", " + glsl_float(p[0]);
    else {
      out += ", vec" + std::to_string(d.size) + "(";
      for (int i = 0; i < d.size; ++i) out += glsl_float(p[i]) + (i + 1 < d.size ? ", " : ")");
    }
    p += d.size;
  }
  return out;
}

}  // namespace

std::string graph_op_expr(int fn, const std::string& a, const std::string& b, const std::string* params) {
  const GraphOperator& op = graph_operators()[static_cast<std::size_t>(fn)];
  std::string call = std::string(op.name) + "(" + a + ".x, " + b + ".x";
  for (std::size_t i = 0; i < op.params.size(); ++i) call += ", " + params[i];
  call += ")";
  std::string mat;
  switch (op.family) {
    case OpFamily::union_: mat = a + ".x < " + b + ".x ? " + a + ".y : " + b + ".y"; break;
    case OpFamily::intersection: mat = a + ".x > " + b + ".x ? " + a + ".y : " + b + ".y"; break;
    case OpFamily::subtraction: mat = a + ".x > -" + b + ".x ? " + a + ".y : " + b + ".y"; break;
    case OpFamily::other: mat = a + ".y"; break;
  }
  return "vec2(" + call + ", " + mat + ")";
}

std::vector<int> graph_frames(const SceneGraph& g) {
  std::vector<int> f(g.nodes.size(), -1);
  for (int i = g.root; i >= 0; --i) {  // parents come after their children
    const GraphNode& n = g.nodes[static_cast<std::size_t>(i)];
    if (n.leaf) continue;
    const int inner = n.unary ? i : f[static_cast<std::size_t>(i)];
    f[static_cast<std::size_t>(n.left)] = inner;
    if (n.right != -1) f[static_cast<std::size_t>(n.right)] = inner;
  }
  return f;
}

namespace {

// A modifier's statements: its child's frame (msFrameI) at the point its
// begin function gives, then its end function; a repetition's loop over
// the copies its point must look at.
std::string modifier_glsl(const SceneGraph& g, std::size_t i) {
  const GraphNode& n = g.nodes[i];
  const GraphUnary& u = graph_unaries()[static_cast<std::size_t>(n.fn)];
  const std::string id = std::to_string(i), v = "n" + id, q = "q" + id, frame = "msFrame" + id;
  const std::string args = leaf_args(u.params, g.params.data() + n.param);
  std::string s = "  vec3 " + q + " = " + local_point(n) + ";\n";
  if (u.copies) {
    const float* floor = g.params.data() + n.param + param_floats(u.params) - kCopyFloorFloats;
    std::string fl;
    for (int k = 0; k < 2; ++k)
      fl += ", vec3(" + glsl_float(floor[3 * k]) + ", " + glsl_float(floor[3 * k + 1]) + ", " + glsl_float(floor[3 * k + 2]) + ")";
    fl += ", " + glsl_float(floor[6]);
    s += "  vec2 " + v + " = vec2(1e30, 0.0);\n  float c" + id + " = 1.0;\n";
    s += "  for (float t = 0.0; t < c" + id + "; t += 1.0) {\n";
    s += "    vec3 c = " + std::string(u.begin) + "(" + q + args + ", t, c" + id + ");\n";
    s += "    if (t > 0.5 && opCopyFloor(c" + fl + ") >= " + v + ".x) continue;\n";
    s += "    vec2 w = " + frame + "(c);\n    if (w.x < " + v + ".x) " + v + " = w;\n  }\n";
  } else {
    const std::string at = u.begin.empty() ? q : std::string(u.begin) + "(" + q + args + ")";
    s += "  vec2 " + v + " = " + frame + "(" + at + ");\n";
    if (!u.end.empty())
      s += "  " + v + ".x = " + std::string(u.end) + "(" + v + ".x" + (u.end_point ? ", " + q : "") + args + ");\n";
  }
  if (n.scale != 1.0f) s += "  " + v + ".x *= " + glsl_float(n.scale) + ";\n";
  return s;
}

}  // namespace

std::string graph_map_inline(const SceneGraph& g) {
  std::string out = "#include \"aov.glsl\"\n// map() generated from the scene graph: " + std::to_string(g.primitives) + " primitives, " +
                    std::to_string(g.operators) + " operators\n";
  const std::vector<int> frames = graph_frames(g);
  // One function a frame: each modifier's child's (inner ones first, as
  // the nodes are in postfix order), then map(), the world's.
  std::vector<int> heads;
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    if (g.nodes[i].unary) heads.push_back(static_cast<int>(i));
  heads.push_back(-1);
  for (int head : heads) {
    std::string body;
    int leaves = 0;
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      if (frames[i] != head) continue;
      const GraphNode& n = g.nodes[i];
      const float* p = g.params.data() + n.param;
      const std::string v = "n" + std::to_string(i);
      if (n.leaf) {
        const GraphPrimitive& prim = graph_primitives()[static_cast<std::size_t>(n.fn)];
        std::string d = std::string(prim.name) + "(" + (prim.dims == 2 ? "(" + local_point(n) + ").xy" : local_point(n)) +
                        leaf_args(prim.params, p) + ")";
        if (n.scale != 1.0f) d += " * " + glsl_float(n.scale);
        body += "  vec2 " + v + " = vec2(" + d + ", " + std::to_string(n.material) + ".0);\n";
        ++leaves;
        continue;
      }
      if (n.unary) {
        body += modifier_glsl(g, i);
        continue;
      }
      const GraphOperator& op = graph_operators()[static_cast<std::size_t>(n.fn)];
      std::vector<std::string> args;
      for (std::size_t k = 0, off = 0; k < op.params.size(); off += static_cast<std::size_t>(op.params[k].size), ++k)
        args.push_back(glsl_float(p[off]));
      body += "  vec2 " + v + " = " +
              graph_op_expr(n.fn, "n" + std::to_string(n.left), "n" + std::to_string(n.right), args.data()) + ";\n";
    }
    const int result = head == -1 ? g.root : g.nodes[static_cast<std::size_t>(head)].left;
    out += (head == -1 ? std::string("vec2 map(vec3 p) {\n") : "vec2 msFrame" + std::to_string(head) + "(vec3 p) {\n") +
           body + "  MS_COUNT_PRIMS(" + std::to_string(leaves) + ");\n  return n" + std::to_string(result) + ";\n}\n";
  }
  return out;
}

}  // namespace ms
