#include "scene/camera_frame.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ms {
namespace {

constexpr float kPi = 3.14159265358979f;

glm::vec3 normalize_or(glm::vec3 v, glm::vec3 fallback) {
  const float l2 = glm::dot(v, v);
  return l2 > 1e-30f ? v / std::sqrt(l2) : fallback;
}

}  // namespace

CameraFrame camera_frame(const Camera& cam) {
  CameraFrame f;
  f.forward = normalize_or(cam.target - cam.position, {0.0f, 0.0f, 1.0f});
  glm::vec3 up = normalize_or(cam.up, {0.0f, 1.0f, 0.0f});
  if (std::abs(glm::dot(f.forward, up)) > 0.9999f)
    up = std::abs(f.forward.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
  f.right = glm::normalize(glm::cross(f.forward, up));
  f.up = glm::cross(f.right, f.forward);
  const float fovy = cam.fov_deg * kPi / 180.0f;
  f.tan_half_fov = std::tan(0.5f * std::clamp(fovy, 1e-4f, kPi - 1e-3f));
  return f;
}

}  // namespace ms
