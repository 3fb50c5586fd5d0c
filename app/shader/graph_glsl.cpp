#include "shader/graph_glsl.h"

#include <cmath>

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

// A leaf's parameters as GLSL arguments: floats, vec2s, vec3s.
std::string leaf_args(const GraphPrimitive& prim, const float* p) {
  std::string out;
  for (const GraphParam& d : prim.params) {
    if (d.size == 1) out += ", " + glsl_float(p[0]);
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

std::string graph_map_inline(const SceneGraph& g) {
  std::string out = "#include \"aov.glsl\"\n// map() generated from the scene graph: " + std::to_string(g.primitives) + " primitives, " +
                    std::to_string(g.operators) + " operators\n";
  out += "vec2 map(vec3 p) {\n";
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const GraphNode& n = g.nodes[i];
    const float* p = g.params.data() + n.param;
    const std::string v = "n" + std::to_string(i);
    if (n.leaf) {
      const GraphPrimitive& prim = graph_primitives()[static_cast<std::size_t>(n.fn)];
      std::string d = std::string(prim.name) + "(" + local_point(n) + leaf_args(prim, p) + ")";
      if (n.scale != 1.0f) d += " * " + glsl_float(n.scale);
      out += "  vec2 " + v + " = vec2(" + d + ", " + std::to_string(n.material) + ".0);\n";
      continue;
    }
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(n.fn)];
    std::vector<std::string> args;
    for (std::size_t k = 0, off = 0; k < op.params.size(); off += static_cast<std::size_t>(op.params[k].size), ++k)
      args.push_back(glsl_float(p[off]));
    out += "  vec2 " + v + " = " +
           graph_op_expr(n.fn, "n" + std::to_string(n.left), "n" + std::to_string(n.right), args.data()) + ";\n";
  }
  out += "  MS_COUNT_PRIMS(" + std::to_string(g.primitives) + ");\n";
  out += "  return n" + std::to_string(g.root) + ";\n}\n";
  return out;
}

}  // namespace ms
