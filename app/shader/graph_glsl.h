// A scene graph as GLSL (docs/scene-graph.md): `vec2 map(vec3 p)` written
// out as straight-line calls to the library with every parameter and
// transform a literal, so it specializes like a hand-written map().
//
//   const std::string glsl = graph_map_inline(*scene.graph);
#pragma once
#include <string>
#include <vector>

#include "scene/graph.h"

namespace ms {

// map() evaluating every node: each leaf at its folded transform, each
// operator on its children with the material of the child that decides
// (the nearer for a union, the farther for an intersection, a's outside a
// subtraction's cut).
std::string graph_map_inline(const SceneGraph& g);

// The GLSL that combines two (distance, material) values by operator `fn`
// with its parameters given as GLSL expressions: shared by the inline map
// and the interpreter, so both compute the same field.
// Per node, the modifier whose frame it is in (its nearest modifier
// ancestor), or -1 for the world's.
std::vector<int> graph_frames(const SceneGraph& g);

std::string graph_op_expr(int fn, const std::string& a, const std::string& b, const std::string* params);

}  // namespace ms
