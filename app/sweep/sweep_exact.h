// The exact-intersection depth reference for scenes of analytic primitives:
// a CPU ray caster, in double precision, for scenes whose map() is a union of
// constant spheres (recognised from the GLSL) plus their declared [[planes]].
// The seed scene is one. The camera mirrors sdf_shaders/camera.glsl (pinhole
// look-at, one sample at each pixel centre). No GL here.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace ms {

struct ExactSphere {
  glm::dvec3 center{0.0};
  double radius = 1.0;
  int material = 0;
};

// The spheres of a map() whose body only declares and returns
//   vec2(sdSphere(p - vec3(x, y, z), r), MAT_NAME)   (or sdSphere(p, r))
// combined with opUnion: nullopt for anything else (other primitives,
// operators, uniforms, loops), with the reason in `why`. Comments are
// ignored. `materials` resolves MAT_<NAME>.
std::optional<std::vector<ExactSphere>> parse_sphere_map(std::string_view map_glsl,
                                                         const std::vector<Material>& materials, std::string* why);

// Per pixel, top row first: whether the pixel centre's primary ray hits a
// sphere or a plane within max_distance, and the ray distance t (0 on a miss).
struct ExactDepth {
  int width = 0, height = 0;
  std::vector<unsigned char> hit;
  std::vector<double> t;
};
ExactDepth exact_depth(const Camera& camera, int width, int height, const std::vector<ExactSphere>& spheres,
                       const std::vector<Plane>& planes, double max_distance);

// The spheres of `scene`'s map() (its map file read from disk), or nullopt
// with the reason in `why`.
std::optional<std::vector<ExactSphere>> exact_spheres(const Scene& scene, std::string* why);

// exact_depth() for `scene`'s spheres and planes, or nullopt with the reason
// in `why`.
std::optional<ExactDepth> exact_reference(const Scene& scene, int width, int height, double max_distance,
                                          std::string* why);

// The defines (AssembleOptions::defines) that make trace() intersect these
// spheres and the scene's planes exactly (sdf_shaders/exact.glsl): the
// exact-intersection reference image, shaded like any other.
std::vector<std::pair<std::string, std::string>> exact_sphere_defines(const std::vector<ExactSphere>& spheres);

}  // namespace ms
