#include "scene/graph_transform.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "core/format.h"

namespace ms {

glm::mat3 axis_angle(glm::vec3 axis, float degrees) {
  const float a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  const glm::vec3 u = glm::normalize(axis);
  glm::mat3 r;  // Rodrigues, column-major: r[col][row]
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[j][i] = (i == j ? c : 0.0f) + (1.0f - c) * u[i] * u[j];
  r[1][0] -= s * u.z; r[2][0] += s * u.y;
  r[0][1] += s * u.z; r[2][1] -= s * u.x;
  r[0][2] -= s * u.y; r[1][2] += s * u.x;
  return r;
}

// The node's local-to-parent map x -> l x + t, with l a rotation times s;
// composed under the parent's world-to-local map.
GraphAffine GraphTransformReader::transform(int v, const GraphAffine& parent, int dims) const {
  glm::mat3 rot{1.0f};
  glm::vec3 t{0.0f};
  float s = 1.0f;
  if (dims == 2) return transform_2d(v, parent);
  if (const int m = doc_.member(v, "matrix"); m != -1) {
    for (const char* other : {"translate", "rotate", "scale"})
      if (doc_.member(v, other) != -1) fail(m, std::string("'matrix' and '") + other + "' exclude each other");
    const std::vector<float> x = numbers(m, 12, "'matrix'");
    glm::mat3 l;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) l[j][i] = x[static_cast<std::size_t>(i * 4 + j)];
      t[i] = x[static_cast<std::size_t>(i * 4 + 3)];
    }
    const float det = glm::determinant(l);
    if (!(det > 0.0f)) fail(m, "'matrix' must be a rotation times a uniform scale", "its determinant is not positive");
    s = std::cbrt(det);
    const glm::mat3 g = glm::transpose(l) * l / (s * s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (std::fabs(g[i][j] - (i == j ? 1.0f : 0.0f)) > 1e-4f)
          fail(m, "'matrix' must be a rotation times a uniform scale (within 1e-4)",
               "shear or non-uniform scale breaks the distance bound");
    rot = l / s;
  } else {
    if (const int c = doc_.member(v, "scale"); c != -1) {
      s = number(c, "'scale'");
      if (!(s > 0.0f)) fail(c, "'scale' must be > 0", "a uniform scale factor");
    }
    if (const int c = doc_.member(v, "rotate"); c != -1) {
      const std::vector<float> r = numbers(c, 4, "'rotate'");
      const glm::vec3 axis{r[0], r[1], r[2]};
      if (!(glm::length(axis) > 1e-12f)) fail(c, "'rotate' needs a non-zero axis", "[axis x, y, z, degrees]");
      rot = axis_angle(axis, r[3]);
    }
    if (const int c = doc_.member(v, "translate"); c != -1) {
      const std::vector<float> x = numbers(c, 3, "'translate'");
      t = {x[0], x[1], x[2]};
    }
  }
  const int own = doc_.member(v, "matrix") != -1 ? doc_.member(v, "matrix") : doc_.member(v, "scale");
  return compose(v, parent, rot, t, s, own);
}

// A profile's transforms, in its plane: translate [x, y], rotate by
// degrees about z, a uniform scale.
GraphAffine GraphTransformReader::transform_2d(int v, const GraphAffine& parent) const {
  if (const int m = doc_.member(v, "matrix"); m != -1)
    fail(m, "a 2D profile takes 'translate' [x, y], 'rotate' (degrees) and 'scale', not 'matrix'");
  glm::mat3 rot{1.0f};
  glm::vec3 t{0.0f};
  float s = 1.0f;
  if (const int c = doc_.member(v, "scale"); c != -1) {
    s = number(c, "'scale'");
    if (!(s > 0.0f)) fail(c, "'scale' must be > 0", "a uniform scale factor");
  }
  if (const int c = doc_.member(v, "rotate"); c != -1) {
    if (doc_.at(c).kind != JsonKind::number) fail(c, "a 2D profile's 'rotate' is one angle in degrees (about z)");
    rot = axis_angle({0.0f, 0.0f, 1.0f}, number(c, "'rotate'"));
  }
  if (const int c = doc_.member(v, "translate"); c != -1) {
    const std::vector<float> x = numbers(c, 2, "a 2D profile's 'translate'");
    t = {x[0], x[1], 0.0f};
  }
  return compose(v, parent, rot, t, s, doc_.member(v, "scale"));
}

// The node's local-to-parent map x -> rot s x + t under the parent's
// world-to-local map; `own` is the key the scale came from, for messages.
GraphAffine GraphTransformReader::compose(int v, const GraphAffine& parent, const glm::mat3& rot, glm::vec3 t, float s, int own) const {
  // The whole chain's scale, and what it does to the translation, must be
  // a float the shader can use: else the box overflows and the graph would
  // look unbounded.
  const double total = static_cast<double>(parent.s) * s;
  if (total > kMaxCoord || total < 1.0 / kMaxCoord)
    fail(own, "the scales from the root down to this node multiply to " + format_number(total) +
                  (total > 1.0 ? ", past the 1e+18" : ", under the 1e-18") + " float coordinates hold");
  // q = l^-1 (q_parent - t), l^-1 = rot^T / s.
  const glm::mat3 inv = glm::transpose(rot) / s;
  const GraphAffine out{inv * parent.a, inv * (parent.b - t), static_cast<float>(total)};
  if (!std::isfinite(out.b.x) || !std::isfinite(out.b.y) || !std::isfinite(out.b.z))
    fail(doc_.member(v, "translate") != -1 ? doc_.member(v, "translate") : own != -1 ? own : v,
         "the translation, in this node's units (the scales above divide it), is past float range");
  return out;
}

}  // namespace ms
