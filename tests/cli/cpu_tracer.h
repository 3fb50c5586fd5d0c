// An independent CPU sphere tracer for the seed scene (a unit sphere at
// (0,1,0) on the plane y = 0), float32 like the GPU, that mirrors
// sdf_shaders/camera.glsl (pinhole look-at camera, ray differentials, pixel
// centres at floor(gl_FragCoord) + 0.5) and trace.glsl's loop (tolerance
// max(HIT_EPSILON, HIT_TOLERANCE * t * spread), step d / LIPSCHITZ, budget
// MAX_STEPS, stop beyond MAX_DIST). Also exact ray-sphere and ray-plane
// intersection in double, for checking depths. Written from the GLSL, not
// from the host code, so it checks the counting pass independently.
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "camera.h"
#include "scene/scene.h"

namespace ms::test {

struct CpuRay {
  glm::vec3 o, d;
  float spread = 0;  // max(|dD/dx|, |dD/dy|): the pixel cone's angle
};

// The primary ray through pixel (x, y), y counted from the TOP row (images
// are stored top row first; GL's gl_FragCoord.y counts from the bottom).
inline CpuRay cpu_camera_ray(const Camera& cam, int width, int height, int x, int y_top) {
  const float fovy = cam.fov_deg * 3.14159265358979f / 180.0f;  // as render/uniforms.cpp
  const auto [fw, right, upv] = camera_basis(cam);
  const float th = std::tan(0.5f * std::clamp(fovy, 1e-4f, 3.14159265358979f - 1e-3f));
  const float invH = 1.0f / std::max(static_cast<float>(height), 1.0f);
  const glm::vec2 res(static_cast<float>(width), static_cast<float>(height));
  const glm::vec2 pix(static_cast<float>(x) + 0.5f, static_cast<float>(height - 1 - y_top) + 0.5f);
  const glm::vec2 uv = (2.0f * pix - res) * invH;
  const glm::vec3 v = fw + th * (uv.x * right + uv.y * upv);
  const float s = 2.0f * th * invH;
  auto normalize_diff = [&](glm::vec3 dv) {
    const float vv = glm::dot(v, v);
    return (vv * dv - glm::dot(v, dv) * v) / (vv * std::sqrt(vv));
  };
  CpuRay r;
  r.o = cam.position;
  r.d = glm::normalize(v);
  r.spread = std::max(glm::length(normalize_diff(s * right)), glm::length(normalize_diff(s * upv)));
  return r;
}

// The seed's map(): distance and material (0 floor, 1 ball), opUnion's
// tie-break included (a.x < b.x ? a : b, floor first).
inline glm::vec2 seed_map(glm::vec3 p) {
  const glm::vec2 ground(p.y, 0.0f);
  const glm::vec2 ball(glm::length(p - glm::vec3(0.0f, 1.0f, 0.0f)) - 1.0f, 1.0f);
  return ground.x < ball.x ? ground : ball;
}

struct CpuTrace {
  float t = 0;
  int steps = 0;
  int mat = 0;
  bool hit = false;
  bool capped = false;
};

// trace.glsl's loop, with the scene's quality settings.
inline CpuTrace cpu_trace(const CpuRay& r, const Quality& q) {
  CpuTrace res;
  float t = 0.0f;
  glm::vec2 h(1e20f, 0.0f);
  for (int i = 0; i < q.max_steps; ++i) {
    h = seed_map(r.o + r.d * t);
    res.steps = i + 1;
    const float tol = std::max(q.hit_epsilon, q.hit_tolerance * (0.0f + t * r.spread));
    if (h.x < tol) {
      res.hit = true;
      break;
    }
    t += h.x / q.lipschitz;
    if (t > q.max_distance) break;
  }
  res.capped = !res.hit && t <= q.max_distance;
  res.hit = res.hit || res.capped;
  res.t = std::min(t, q.max_distance);
  res.mat = static_cast<int>(h.y + 0.5f);
  return res;
}

// The hit tolerance trace.glsl uses at distance t on this ray.
inline double cpu_tolerance(const CpuRay& r, const Quality& q, double t) {
  return std::max<double>(q.hit_epsilon, q.hit_tolerance * t * r.spread);
}

struct ExactHit {
  bool hit = false;
  double t = 0;       // ray distance to the first surface
  int mat = 0;        // 0 floor, 1 ball
  glm::dvec3 n{0.0};  // the surface normal there
};

// Exact first intersection with the sphere and the plane (double), up to `tmax`.
inline ExactHit exact_seed_hit(const CpuRay& r, double tmax) {
  const glm::dvec3 o(r.o), d = glm::normalize(glm::dvec3(r.d)), c(0.0, 1.0, 0.0);
  ExactHit best;
  best.t = tmax;
  if (d.y < 0.0) {  // the plane y = 0, seen from above
    const double t = -o.y / d.y;
    if (t > 0.0 && t <= best.t) best = {true, t, 0, {0.0, 1.0, 0.0}};
  }
  const glm::dvec3 oc = o - c;
  const double b = glm::dot(oc, d), cc = glm::dot(oc, oc) - 1.0, disc = b * b - cc;
  if (disc >= 0.0) {
    const double t = -b - std::sqrt(disc);
    if (t > 0.0 && t <= best.t) best = {true, t, 1, glm::normalize(o + t * d - c)};
  }
  if (!best.hit) best.t = 0.0;
  return best;
}

// Exact distance from p to material `mat`'s surface (0 plane, 1 sphere).
inline double exact_distance_to(int mat, glm::dvec3 p) {
  return mat == 0 ? std::abs(p.y) : std::abs(glm::length(p - glm::dvec3(0.0, 1.0, 0.0)) - 1.0);
}

}  // namespace ms::test
