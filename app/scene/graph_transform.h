// A graph node's transform keys read into its world-to-local map
// (docs/scene-graph.md, "Transforms"): `translate`, `rotate` (axis and
// degrees) and a uniform `scale`, or one `matrix` (a rotation times a
// uniform scale, within 1e-4); a profile's in its plane. Each mistake is
// one line at its JSON pointer.
//
//   GraphAffine xf = reader.transform(v, parent_xf, 3);   // q = xf.a p + xf.b, distances times xf.s
#pragma once
#include <string>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/graph_read.h"

namespace ms {

// World to a node's local space: q = a * p + b, and its distances times s.
struct GraphAffine {
  glm::mat3 a{1.0f};
  glm::vec3 b{0.0f};
  float s = 1.0f;
};

// Rodrigues: the turn by `degrees` about `axis` (any length but 0).
glm::mat3 axis_angle(glm::vec3 axis, float degrees);

class GraphTransformReader : public GraphReader {
 public:
  using GraphReader::GraphReader;
  // Node v's map under its parent's; `dims` 2 for a profile.
  GraphAffine transform(int v, const GraphAffine& parent, int dims) const;

 private:
  GraphAffine transform_2d(int v, const GraphAffine& parent) const;
  GraphAffine compose(int v, const GraphAffine& parent, const glm::mat3& rot, glm::vec3 t, float s, int own) const;
};

}  // namespace ms
