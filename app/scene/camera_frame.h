// The camera's look-at frame: where the primary rays of a pinhole camera
// point. Computed once per frame on the host and handed to
// sdf_shaders/camera.glsl as uniforms (uCamBasis, uCamTanHalfFov), so no
// pixel recomputes it; the CPU references (sweep/sweep_exact.h) use it too.
#pragma once
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace ms {

struct CameraFrame {
  glm::vec3 right{-1.0f, 0.0f, 0.0f};  // unit; image x grows along it
  glm::vec3 up{0.0f, 1.0f, 0.0f};      // unit; image y grows along it
  glm::vec3 forward{0.0f, 0.0f, 1.0f}; // unit view direction
  float tan_half_fov = 0.41421356f;    // tan(vertical fov / 2)
};

// Degenerate input never yields NaN: a zero view vector looks down +z, a
// zero up is +y, an up (nearly) parallel to the view direction is replaced
// by +y or +z, and the fov is kept inside (0, 180) degrees.
CameraFrame camera_frame(const Camera& cam);

}  // namespace ms
