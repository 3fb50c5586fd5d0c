#include "live/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace ms::live {
namespace {

// Rodrigues' rotation of v by `angle` radians about the unit axis k.
glm::vec3 rotate(glm::vec3 v, float angle, glm::vec3 k) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0f - c);
}

glm::vec3 world_up(const Camera& cam) {
  const float len = glm::length(cam.up);
  return len > 0.0f ? cam.up / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

// Rotate `v` by yaw about `up` and by pitch about the horizontal axis
// perpendicular to it, clamping the angle between v and up to
// [kMinPoleAngle, pi - kMinPoleAngle]. `pitch` > 0 tilts v towards up.
glm::vec3 rotate_dir(glm::vec3 v, glm::vec3 up, float yaw, float pitch) {
  const float len = glm::length(v);
  if (len <= 0.0f) return v;
  glm::vec3 d = v / len;
  d = rotate(d, yaw, up);
  const float polar = std::acos(std::clamp(glm::dot(d, up), -1.0f, 1.0f));  // 0 = along up
  const float target_polar = std::clamp(polar - pitch, kMinPoleAngle, 3.14159265f - kMinPoleAngle);
  glm::vec3 horiz = d - up * glm::dot(d, up);
  const float hl = glm::length(horiz);
  if (hl < 1e-6f) {
    // Started on the pole (a scene camera looking straight along up): pick
    // any horizontal direction so the result is still well defined.
    horiz = std::abs(up.x) < 0.9f ? glm::cross(up, glm::vec3(1, 0, 0)) : glm::cross(up, glm::vec3(0, 0, 1));
  }
  horiz = glm::normalize(horiz);
  return (up * std::cos(target_polar) + horiz * std::sin(target_polar)) * len;
}

}  // namespace

float distance_to_target(const Camera& cam) { return glm::length(cam.target - cam.position); }

Frame3 camera_frame(const Camera& cam) {
  Frame3 f;
  const glm::vec3 up = world_up(cam);
  f.forward = glm::normalize(cam.target - cam.position);
  glm::vec3 r = glm::cross(f.forward, up);
  if (glm::length(r) < 1e-6f) r = glm::cross(f.forward, std::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1));
  f.right = glm::normalize(r);
  f.up = glm::cross(f.right, f.forward);
  return f;
}

Camera orbit(const Camera& cam, float yaw, float pitch) {
  Camera out = cam;
  // The eye sits at target + offset; raising the eye means tilting the
  // offset towards up, hence +pitch.
  out.position = cam.target + rotate_dir(cam.position - cam.target, world_up(cam), -yaw, pitch);
  return out;
}

Camera look(const Camera& cam, float yaw, float pitch) {
  Camera out = cam;
  out.target = cam.position + rotate_dir(cam.target - cam.position, world_up(cam), -yaw, pitch);
  return out;
}

Camera pan(const Camera& cam, float dx, float dy, int viewport_height) {
  if (viewport_height <= 0) return cam;
  const Frame3 f = camera_frame(cam);
  // World units per pixel at the target's depth.
  const float tan_half = std::tan(0.5f * glm::radians(cam.fov_deg));
  const float scale = 2.0f * distance_to_target(cam) * tan_half / static_cast<float>(viewport_height);
  // Dragging right moves the scene right, i.e. the camera left.
  const glm::vec3 shift = (-dx * f.right + dy * f.up) * scale;
  Camera out = cam;
  out.position += shift;
  out.target += shift;
  return out;
}

Camera dolly(const Camera& cam, float steps) {
  const float d = distance_to_target(cam);
  const float nd = std::max(kMinDistance, d * std::pow(0.85f, steps));
  Camera out = cam;
  out.position = cam.target - camera_frame(cam).forward * nd;
  return out;
}

Camera fly(const Camera& cam, glm::vec3 move) {
  const Frame3 f = camera_frame(cam);
  const glm::vec3 shift = move.x * f.right + move.y * world_up(cam) + move.z * f.forward;
  Camera out = cam;
  out.position += shift;
  out.target += shift;
  return out;
}

}  // namespace ms::live
