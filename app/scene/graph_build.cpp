#include "scene/graph_build.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/error.h"
#include "core/format.h"
#include "io/input_file.h"
#include "scene/graph_read.h"
#include "scene/graph_transform.h"
#include "scene/graph_unary.h"
#include "scene/graph_vocab.h"
#include "core/suggest.h"
#include "scene/toml_read.h"

namespace ms {

namespace {

using Affine = GraphAffine;

constexpr std::string_view kNodeKeys[] = {"sdf", "op", "children", "translate", "rotate", "scale", "matrix",
                                          "material", "name"};

// An operator waiting for its children, folded left as they arrive, or a
// modifier waiting for its one child.
struct Frame {
  int value = -1;
  int fn = -1;
  Affine xf;
  int material = 0;
  std::vector<float> params;  // operators: in their frame's units; modifiers: local
  int next_child = -1;
  int acc = -1;               // the fold so far
  int unary = -1;             // a modifier: graph_unaries()[unary]
  int dims = 3;               // of the children: 2 under extrude and revolve
};

class Builder : GraphTransformReader {
 public:
  Builder(const JsonDoc& doc, std::string display, std::string prefix, const std::vector<Material>& mats)
      : GraphTransformReader(doc, std::move(display), std::move(prefix)), mats_(mats) {}

  SceneGraph build(int root) {
    std::vector<Frame> stack;
    visit(root, Affine{}, 0, 3, stack);
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.next_child != -1) {
        const int child = f.next_child;
        f.next_child = doc_.at(child).next;
        // A modifier's child starts a frame of its own.
        const Affine xf = f.unary == -1 ? f.xf : Affine{};
        const int mat = f.material, dims = f.dims;
        visit(child, xf, mat, dims, stack);  // may push: `f` is not used after
        continue;
      }
      const int done = f.unary == -1 ? f.acc : modifier(f, f.acc);
      if (f.unary != -1) --open_modifiers_;
      stack.pop_back();
      deliver(done, stack);
    }
    g_.root = result_;
    const GraphBox& box = g_.root_node().box;
    if (!box.finite()) fail_unbounded();
    if (box.empty()) fail(root, "the graph is empty: its intersections leave nothing");
    return std::move(g_);
  }

 private:
  // Down from the root, the first child whose box is infinite, to the node
  // whose own box is: an infinite primitive that nothing cuts.
  [[noreturn]] void fail_unbounded() const {
    int at = g_.root;
    for (;;) {
      const GraphNode& n = g_.nodes[static_cast<std::size_t>(at)];
      int next = -1;
      for (int c : {n.left, n.right})
        if (next == -1 && c != -1 && !g_.nodes[static_cast<std::size_t>(c)].box.finite()) next = c;
      if (next == -1) break;
      at = next;
    }
    const GraphNode& n = g_.nodes[static_cast<std::size_t>(at)];
    const std::string what =
        n.leaf ? "an infinite " + std::string(graph_primitives()[static_cast<std::size_t>(n.fn)].name) +
                     " not cut by an intersection"
               : "this node's box is infinite though its children's are not";
    fail(value_[static_cast<std::size_t>(at)], "the graph is unbounded: " + what,
         "intersect it with a bounded shape or subtract it from one; ground planes go in [[planes]]");
  }

  // A node: a leaf is made at once; an operator or modifier is pushed to
  // collect its children. `dims` is 2 inside a profile.
  void visit(int v, const Affine& parent, int inherited, int dims, std::vector<Frame>& stack) {
    if (doc_.at(v).kind != JsonKind::object) fail(v, "a node must be an object with 'sdf' or 'op'");
    check_keys(v);
    const Affine xf = transform(v, parent, dims);
    const int mat = material(v, inherited);
    const int sdf = doc_.member(v, "sdf"), op = doc_.member(v, "op");
    if ((sdf == -1) == (op == -1))
      fail(v, sdf == -1 ? "a node needs 'sdf' (a primitive) or 'op' (a combinator)" : "'sdf' and 'op' exclude each other");
    if (sdf != -1) {
      if (const int c = doc_.member(v, "children"); c != -1) fail(c, "a primitive has no children");
      deliver(leaf(v, sdf, xf, mat, dims), stack);
      return;
    }
    const int children = doc_.member(v, "children");
    if (const int u = unary_of(op); u != -1) {
      const GraphUnary& un = graph_unaries()[static_cast<std::size_t>(u)];
      if (dims == 2 && !un.on_profiles)
        fail(op, quote(un.name) + " cannot be used on a 2D profile", "use it on the extruded or revolved solid");
      if (children == -1 || doc_.at(children).kind != JsonKind::array || doc_.at(children).count != 1)
        fail(children == -1 ? v : children, quote(un.name) + " takes one child: 'children' must be an array of one node");
      if (open_modifiers_ >= kMaxModifierDepth)
        fail(op, "modifiers nest " + std::to_string(kMaxModifierDepth + 1) + " deep here, past the " +
                     std::to_string(kMaxModifierDepth) + " the evaluators take",
             "each is a frame of the interpreter and a function of the inline map()");
      const int child_dims = un.child_dims == 2 ? 2 : dims;
      stack.push_back({v, u, xf, mat, read_params(v, un.params), doc_.at(children).first, -1, u, child_dims});
      ++open_modifiers_;
      ++g_.operators;
      return;
    }
    const int fn = name_of(op, graph_operators(), "combinator");
    if (children == -1) fail(v, "an operator needs 'children'", "two or more nodes");
    if (doc_.at(children).kind != JsonKind::array || doc_.at(children).count < 2)
      fail(children, "'children' must be an array of two or more nodes");
    Frame f{v, fn, xf, mat, read_params(v, graph_operators()[static_cast<std::size_t>(fn)].params), doc_.at(children).first, -1};
    f.dims = dims;
    const auto& defs = graph_operators()[static_cast<std::size_t>(fn)].params;
    for (std::size_t i = 0, k = 0; i < defs.size(); k += static_cast<std::size_t>(defs[i].size), ++i)
      if (defs[i].length)
        for (int j = 0; j < defs[i].size; ++j) {
          const double world = static_cast<double>(f.params[k + static_cast<std::size_t>(j)]) * xf.s;
          if (std::fabs(world) > kMaxCoord)
            fail(doc_.member(v, defs[i].name), quote(defs[i].name) + " times the scales above it is " +
                                                   format_number(world) + ", past the 1e+18 float lengths hold");
          f.params[k + static_cast<std::size_t>(j)] = static_cast<float>(world);
        }
    ++g_.operators;
    stack.push_back(std::move(f));
  }

  // The modifier's index when `op` names one, else -1 (an unknown name is
  // reported by name_of() with the combinators' and modifiers' names).
  int unary_of(int op) const {
    if (doc_.at(op).kind != JsonKind::string) return -1;
    const std::string_view name = doc_.text(op);
    if (find_operator(name) != -1) return -1;
    return find_unary(name);
  }

  // A modifier over its finished child: its box and bound from the child's,
  // in its own frame, then in its parent's.
  int modifier(const Frame& f, int child) {
    const GraphUnary& un = graph_unaries()[static_cast<std::size_t>(f.unary)];
    GraphNode n;
    n.leaf = false;
    n.unary = true;
    n.fn = f.unary;
    n.left = child;
    std::vector<float> params = f.params;
    const GraphNode& c = g_.nodes[static_cast<std::size_t>(child)];
    const std::string why = un.shape(c, params.data(), n);
    if (!why.empty()) fail(f.value, quote(un.name) + ": " + why);
    if (n.core.empty()) fail(f.value, quote(un.name) + " leaves nothing: its child is empty");
    n.lipschitz *= c.lipschitz;
    // Past this a march would crawl: every step divided by the bound.
    if (!(n.lipschitz <= 1e6f))
      fail(f.value, quote(un.name) + " has a Lipschitz bound of " + format_number(n.lipschitz) + ", past the 1e+06 a march can use",
           "a smaller rate, or a smaller child");
    n.param = static_cast<int>(g_.params.size());
    g_.params.insert(g_.params.end(), params.begin(), params.end());
    n.material = c.material;
    n.to_local = f.xf.a;
    n.offset = f.xf.b;
    n.scale = f.xf.s;
    n.core = world_box(f.value, n.core, f.xf);
    n.slack *= f.xf.s;
    n.box = box_grow(n.core, n.slack);
    n.line = doc_.at(f.value).line;
    g_.nodes.push_back(n);
    value_.push_back(f.value);
    return static_cast<int>(g_.nodes.size()) - 1;
  }

  // A finished subtree: the root, or the next child of the operator on top.
  void deliver(int id, std::vector<Frame>& stack) {
    if (stack.empty()) {
      result_ = id;
      return;
    }
    Frame& f = stack.back();
    f.acc = f.acc == -1 ? id : combine(f, f.acc, id);
  }

  int combine(const Frame& f, int a, int b) {
    const GraphOperator& op = graph_operators()[static_cast<std::size_t>(f.fn)];
    GraphNode n;
    n.leaf = false;
    n.fn = f.fn;
    n.left = a;
    n.right = b;
    n.param = static_cast<int>(g_.params.size());
    g_.params.insert(g_.params.end(), f.params.begin(), f.params.end());
    const GraphNode& na = g_.nodes[static_cast<std::size_t>(a)];
    const GraphNode& nb = g_.nodes[static_cast<std::size_t>(b)];
    op.box(na, nb, f.params.data(), n);
    n.box = box_grow(n.core, n.slack);
    n.lipschitz = op.lipschitz * std::max(na.lipschitz, nb.lipschitz);
    n.line = doc_.at(f.value).line;
    g_.nodes.push_back(n);
    value_.push_back(f.value);
    return static_cast<int>(g_.nodes.size()) - 1;
  }

  int leaf(int v, int sdf, const Affine& xf, int mat, int dims) {
    const int fn = name_of(sdf, graph_primitives(), "primitive");
    const GraphPrimitive& prim = graph_primitives()[static_cast<std::size_t>(fn)];
    if (prim.dims == 2 && dims == 3)
      fail(sdf, "the 2D profile " + quote(prim.name) + " must be inside an 'extrude' or 'revolve'",
           "a profile is a shape of the plane: extrude or revolve it into a solid");
    if (prim.dims == 3 && dims == 2)
      fail(sdf, "the solid " + quote(prim.name) + " cannot be part of a 2D profile",
           "under 'extrude' and 'revolve' only 2D shapes (sd2*) and their combinations");
    GraphNode n;
    n.fn = fn;
    n.param = static_cast<int>(g_.params.size());
    const std::vector<float> p = read_params(v, prim.params);
    g_.params.insert(g_.params.end(), p.begin(), p.end());
    n.material = mat;
    n.to_local = xf.a;
    n.offset = xf.b;
    n.scale = xf.s;
    n.box = n.core = world_box(v, prim.box(p.data()), xf);
    n.lipschitz = prim.lipschitz;
    n.line = doc_.at(v).line;
    ++g_.primitives;
    g_.nodes.push_back(n);
    value_.push_back(v);
    return static_cast<int>(g_.nodes.size()) - 1;
  }

  // The local box mapped to world space by interval arithmetic on
  // p = a^-1 (q - b); a^-1 = s^2 a^T since a is a rotation over s. In
  // double, so that a finite box too large for float is refused as that,
  // and only an infinite primitive makes an infinite box.
  GraphBox world_box(int v, const GraphBox& local, const Affine& xf) const {
    const glm::dmat3 inv = glm::transpose(glm::dmat3(xf.a)) * (static_cast<double>(xf.s) * xf.s);
    const glm::dvec3 origin = -(inv * glm::dvec3(xf.b));
    glm::dvec3 lo = origin, hi = origin;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double m = inv[j][i];  // row i, column j: |m| <= s; a rotation's float zeros are ~1e-8
        if (std::fabs(m) < 1e-7 * xf.s) continue;
        const double a = m * local.min[j], b = m * local.max[j];
        lo[i] += std::min(a, b);
        hi[i] += std::max(a, b);
      }
    const glm::dvec3 far = glm::max(glm::abs(lo), glm::abs(hi));
    for (int i = 0; i < 3; ++i)
      if (std::isfinite(far[i]) && far[i] > kMaxCoord)
        fail(v, "its box reaches " + format_number(far[i]) + " along " + "xyz"[i] +
                    ", past the 1e+18 float coordinates hold",
             "its size and position, times the scales above it, must stay within 1e+18");
    // Float rounding of the transform must not cut the surface; an
    // infinite side (a half-space's) must not spread to the others.
    glm::dvec3 finite_far = far;
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(finite_far[i])) finite_far[i] = 0.0;
    const double pad = 1e-5 * (1.0 + glm::length(finite_far));
    return box_grow(GraphBox{glm::vec3(lo), glm::vec3(hi)}, static_cast<float>(pad));
  }

  void check_keys(int v) const {
    for (int c = doc_.at(v).first; c != -1; c = doc_.at(c).next) {
      const std::string_view k = doc_.key(c);
      bool known = false;
      for (std::string_view n : kNodeKeys) known = known || n == k;
      if (known) continue;
      // A parameter of the node's function is known too; checked in read_params.
      if (is_param(v, k)) continue;
      std::vector<std::string_view> cands(std::begin(kNodeKeys), std::end(kNodeKeys));
      const std::vector<GraphParam>* defs = params_of(v);
      if (defs)
        for (const GraphParam& p : *defs)
          if (!p.derived) cands.push_back(p.name);
      fail(c, "unknown key " + quote(k), did_you_mean(k, cands));
    }
  }

  const std::vector<GraphParam>* params_of(int v) const {
    if (const int s = doc_.member(v, "sdf"); s != -1 && doc_.at(s).kind == JsonKind::string)
      if (const int fn = find_primitive(doc_.text(s)); fn != -1) return &graph_primitives()[static_cast<std::size_t>(fn)].params;
    if (const int o = doc_.member(v, "op"); o != -1 && doc_.at(o).kind == JsonKind::string) {
      if (const int fn = find_operator(doc_.text(o)); fn != -1) return &graph_operators()[static_cast<std::size_t>(fn)].params;
      if (const int u = find_unary(doc_.text(o)); u != -1) return &graph_unaries()[static_cast<std::size_t>(u)].params;
    }
    return nullptr;
  }
  bool is_param(int v, std::string_view k) const {
    const std::vector<GraphParam>* defs = params_of(v);
    if (!defs) return true;  // the unknown function is reported first
    for (const GraphParam& p : *defs)
      if (p.name == k && !p.derived) return true;
    return false;
  }

  template <class T>
  int name_of(int v, std::span<const T> list, const char* what) const {
    if (doc_.at(v).kind != JsonKind::string) fail(v, std::string("the ") + what + " must be named by a string");
    const std::string_view name = doc_.text(v);
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i].name == name) return static_cast<int>(i);
    std::vector<std::string_view> names;
    for (const T& t : list) names.push_back(t.name);
    if (std::string_view(what) == "combinator")
      for (const GraphUnary& u : graph_unaries()) names.push_back(u.name);
    fail(v, std::string("unknown ") + what + " " + quote(name), did_you_mean(name, names));
  }

  int material(int v, int inherited) const {
    const int m = doc_.member(v, "material");
    if (m == -1) return inherited;
    if (doc_.at(m).kind != JsonKind::string) fail(m, "'material' must be a string naming a [[materials]] entry");
    std::vector<std::string_view> names;
    for (std::size_t i = 0; i < mats_.size(); ++i) {
      if (mats_[i].name == doc_.text(m)) return static_cast<int>(i);
      names.push_back(mats_[i].name);
    }
    fail(m, "unknown material " + quote(doc_.text(m)), did_you_mean(doc_.text(m), names));
  }

  const std::vector<Material>& mats_;
  SceneGraph g_;
  std::vector<int> value_;  // per node of g_, its JSON value (an operator's: the fold's)
  int result_ = -1;
  int open_modifiers_ = 0;  // modifiers on the stack: how deep they nest here
};

}  // namespace

SceneGraph build_graph(const JsonDoc& doc, int node, const std::string& display, const std::string& prefix,
                       const std::vector<Material>& materials) {
  if (materials.empty()) fail_input("a graph scene needs at least one [[materials]] entry", display, 0, "materials");
  return Builder(doc, display, prefix, materials).build(node);
}

SceneGraph load_graph_file(const std::filesystem::path& file, std::vector<Material>& materials) {
  const std::string display = file.string();
  // A node takes two values or more ("sdf" and its object, or "op", its
  // object, its children), and an operator's frame two levels (its object
  // and the children's array).
  const JsonCost builder{sizeof(GraphNode) / 2 + sizeof(float), sizeof(Frame) / 2};
  const JsonDoc doc = parse_json_doc(read_input_file(file, "graph file"), display, builder);
  if (doc.at(0).kind != JsonKind::object) fail_input("a graph file must be an object {\"root\": NODE}", display, 1);
  for (int c = doc.at(0).first; c != -1; c = doc.at(c).next)
    if (doc.key(c) != "root")
      fail_input("unknown key " + quote(doc.key(c)), display, doc.at(c).line, doc.pointer(c),
                 "a graph file holds only \"root\"");
  const int root = doc.member(0, "root");
  if (root == -1) fail_input("missing \"root\"", display, 1, "", "a graph file is {\"root\": NODE}");
  if (materials.empty()) materials = graph_default_materials(doc, display, "");
  SceneGraph g = build_graph(doc, root, display, "", materials);
  g.file = file;
  return g;
}

}  // namespace ms
