// live/camera.h: the viewer's camera controls keep their invariants (orbit
// keeps the distance and the target, never flips over the pole; pan keeps
// the view direction and follows the cursor; dolly never passes the target;
// fly moves eye and target together) and the scene's up vector survives.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "live/camera.h"

namespace ms::live {
namespace {

Camera seed_camera() {
  Camera c;
  c.position = {0.0f, 1.6f, -5.0f};
  c.target = {0.0f, 0.8f, 0.0f};
  c.up = {0.0f, 1.0f, 0.0f};
  c.fov_deg = 45.0f;
  return c;
}

void expect_near(glm::vec3 a, glm::vec3 b, float eps = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(LiveCamera, OrbitKeepsTargetDistanceAndUp) {
  const Camera c = seed_camera();
  const Camera o = orbit(c, 0.7f, 0.3f);
  expect_near(o.target, c.target);
  EXPECT_NEAR(distance_to_target(o), distance_to_target(c), 1e-4f);
  expect_near(o.up, c.up);
  EXPECT_GT(glm::length(o.position - c.position), 0.5f);
}

TEST(LiveCamera, OrbitYawAloneKeepsHeight) {
  const Camera c = seed_camera();
  const Camera o = orbit(c, 1.0f, 0.0f);
  EXPECT_NEAR(o.position.y, c.position.y, 1e-4f);
}

TEST(LiveCamera, FullTurnComesBack) {
  const Camera c = seed_camera();
  Camera o = c;
  for (int i = 0; i < 8; ++i) o = orbit(o, 2.0f * 3.14159265f / 8.0f, 0.0f);
  expect_near(o.position, c.position, 1e-3f);
}

TEST(LiveCamera, PositivePitchRaisesTheEye) {
  const Camera c = seed_camera();
  EXPECT_GT(orbit(c, 0.0f, 0.2f).position.y, c.position.y);
  EXPECT_LT(orbit(c, 0.0f, -0.2f).position.y, c.position.y);
}

TEST(LiveCamera, PitchStopsShortOfThePoles) {
  const Camera c = seed_camera();
  for (float pitch : {10.0f, -10.0f}) {
    const Camera o = orbit(c, 0.0f, pitch);
    const glm::vec3 d = glm::normalize(o.target - o.position);
    const float angle = std::acos(std::abs(glm::dot(d, c.up)));
    EXPECT_GE(angle, kMinPoleAngle * 0.99f) << pitch;
    EXPECT_NEAR(distance_to_target(o), distance_to_target(c), 1e-3f);
  }
}

TEST(LiveCamera, OrbitFromThePoleIsStillDefined) {
  Camera c;
  c.position = {0, 5, 0};
  c.target = {0, 0, 0};
  c.up = {0, 0, 1};  // the file's explicit up for a top view; orbit is about it
  const Camera o = orbit(c, 0.3f, 0.2f);
  EXPECT_TRUE(std::isfinite(o.position.x) && std::isfinite(o.position.y) && std::isfinite(o.position.z));
  EXPECT_NEAR(distance_to_target(o), 5.0f, 1e-3f);
}

TEST(LiveCamera, LookKeepsTheEye) {
  const Camera c = seed_camera();
  const Camera l = look(c, 0.4f, 0.1f);
  expect_near(l.position, c.position);
  EXPECT_NEAR(distance_to_target(l), distance_to_target(c), 1e-4f);
  EXPECT_GT(glm::length(l.target - c.target), 0.1f);
  EXPECT_GT(look(c, 0.0f, 0.1f).target.y, c.target.y);  // positive pitch looks up
}

TEST(LiveCamera, PanMovesBothAndFollowsTheCursor) {
  const Camera c = seed_camera();
  const int h = 400;
  const Camera p = pan(c, static_cast<float>(h), 0.0f, h);  // a drag of one viewport height, rightwards
  const glm::vec3 shift = p.target - c.target;
  expect_near(p.position - c.position, shift);
  // One viewport height at the target's depth is 2 d tan(fov/2) world units.
  const float expected = 2.0f * distance_to_target(c) * std::tan(glm::radians(c.fov_deg) * 0.5f);
  EXPECT_NEAR(glm::length(shift), expected, 1e-3f);
  // Dragging right moves the camera left (the scene follows the cursor).
  EXPECT_LT(glm::dot(shift, camera_frame(c).right), 0.0f);
  // A downward drag (y grows downwards) moves the camera up.
  EXPECT_GT(glm::dot(pan(c, 0.0f, 10.0f, h).target - c.target, camera_frame(c).up), 0.0f);
}

TEST(LiveCamera, DollyApproachesButNeverPasses) {
  const Camera c = seed_camera();
  const Camera in = dolly(c, 1.0f);
  EXPECT_LT(distance_to_target(in), distance_to_target(c));
  expect_near(in.target, c.target);
  expect_near(glm::normalize(in.target - in.position), glm::normalize(c.target - c.position));
  EXPECT_GT(distance_to_target(dolly(c, -1.0f)), distance_to_target(c));
  const Camera far_in = dolly(c, 10000.0f);
  EXPECT_GE(distance_to_target(far_in), kMinDistance * 0.99f);
  EXPECT_GT(glm::dot(far_in.target - far_in.position, c.target - c.position), 0.0f);
}

TEST(LiveCamera, FlyMovesEyeAndTargetTogether) {
  const Camera c = seed_camera();
  const Camera f = fly(c, {0.0f, 0.0f, 1.0f});
  expect_near(f.position - c.position, f.target - c.target);
  EXPECT_NEAR(glm::length(f.position - c.position), 1.0f, 1e-4f);
  expect_near(glm::normalize(f.position - c.position), camera_frame(c).forward);
  EXPECT_NEAR(fly(c, {0.0f, 2.0f, 0.0f}).position.y - c.position.y, 2.0f, 1e-4f);  // up = world up
}

}  // namespace
}  // namespace ms::live
