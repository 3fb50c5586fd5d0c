// Viewer camera controls as pure functions on the scene's look-at Camera
// (position, target, up, fov): orbit around the target, pan, dolly, look
// around from the eye and fly. No GL, no GLFW: unit-tested on their own.
// `up` is the scene's world up and is never changed, so writing the camera
// back to the TOML keeps the file's up vector.
#pragma once
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace ms::live {

// Radians per pixel of mouse drag for orbit and look.
inline constexpr float kRadiansPerPixel = 0.005f;
// Closest the eye may come to the target, and the smallest angle (radians)
// between the view direction and the up axis (no flip over the pole).
inline constexpr float kMinDistance = 1e-3f;
inline constexpr float kMinPoleAngle = 0.01f;

// Rotate the eye around the target: `yaw` about the up axis, `pitch` about
// the camera's right axis (positive pitch raises the eye). Keeps the distance
// to the target; pitch stops short of the poles.
Camera orbit(const Camera& cam, float yaw, float pitch);

// Rotate the view direction around the eye (first-person look); keeps the
// eye and the eye-target distance.
Camera look(const Camera& cam, float yaw, float pitch);

// Slide eye and target together in the image plane by a drag of (dx, dy)
// pixels (x right, y down) in a viewport `viewport_height` pixels tall: the
// point at the target's depth follows the cursor.
Camera pan(const Camera& cam, float dx, float dy, int viewport_height);

// Move the eye towards the target by a factor per wheel step (positive
// steps move closer). Never reaches or passes the target.
Camera dolly(const Camera& cam, float steps);

// Move eye and target together: `move` is (right, up, forward) in world
// units, along the camera's own axes (up = the world up).
Camera fly(const Camera& cam, glm::vec3 move);

// Unit vectors of the camera frame: forward, right (forward x up), true up.
struct Frame3 {
  glm::vec3 forward, right, up;
};
Frame3 camera_frame(const Camera& cam);

float distance_to_target(const Camera& cam);

}  // namespace ms::live
