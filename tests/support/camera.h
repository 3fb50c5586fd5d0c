// The pinhole look-at camera's basis as sdf_shaders/camera.glsl builds it,
// for tests that project points to pixels or trace rays on the CPU.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ms::test {

struct CameraBasis {
  glm::vec3 forward, right, up;  // orthonormal; `up` is the image's up
};

inline CameraBasis camera_basis(const Camera& cam) {
  const glm::vec3 fw = glm::normalize(cam.target - cam.position);
  const glm::vec3 right = glm::normalize(glm::cross(fw, glm::normalize(cam.up)));
  return {fw, right, glm::cross(right, fw)};
}

}  // namespace ms::test
