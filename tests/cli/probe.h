// Helpers for image-content assertions: project world points to pixels with
// the same pinhole model as sdf_shaders/camera.glsl, and read pixels.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "camera.h"
#include "io/image.h"
#include "scene/scene.h"

namespace ms::test {

struct PixelPos {
  int x = -1, y = -1;  // image coordinates, top row 0
};

inline PixelPos project(const Camera& cam, int width, int height, glm::vec3 p) {
  const auto [fw, right, up] = camera_basis(cam);
  const float th = std::tan(0.5f * glm::radians(cam.fov_deg));
  const glm::vec3 d = p - cam.position;
  const float z = glm::dot(d, fw);
  const glm::vec2 uv(glm::dot(d, right) / z / th, glm::dot(d, up) / z / th);
  const glm::vec2 pix = (uv * static_cast<float>(height) + glm::vec2(width, height)) * 0.5f;  // GL, bottom-up
  return {static_cast<int>(std::floor(pix.x)), height - 1 - static_cast<int>(std::floor(pix.y))};
}

inline glm::vec3 rgb(const Image& img, PixelPos p) {
  return {img.at(p.x, p.y, 0), img.at(p.x, p.y, 1), img.at(p.x, p.y, 2)};
}

inline float luma(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Mean colour of a (2r+1)^2 block, to step over single-pixel noise.
inline glm::vec3 mean_rgb(const Image& img, PixelPos p, int r) {
  glm::vec3 sum(0.0f);
  int n = 0;
  for (int y = p.y - r; y <= p.y + r; ++y)
    for (int x = p.x - r; x <= p.x + r; ++x)
      if (x >= 0 && y >= 0 && x < img.width && y < img.height) {
        sum += rgb(img, {x, y});
        ++n;
      }
  return n ? sum / static_cast<float>(n) : sum;
}

// Does the segment a->b pass within `r` of `c`? (Occlusion by a sphere.)
inline bool segment_near(glm::vec3 a, glm::vec3 b, glm::vec3 c, float r) {
  const glm::vec3 d = b - a;
  const float t = glm::clamp(glm::dot(c - a, d) / glm::dot(d, d), 0.0f, 1.0f);
  return glm::length(a + t * d - c) < r;
}

inline float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// Luminance in linear light of an sRGB-encoded colour: shading ratios
// (shadowed vs lit, dark vs light cell) are meaningful only there.
inline float luma_linear(glm::vec3 c) {
  return luma({srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)});
}

// Chromaticity (rgb / (r+g+b)) of an sRGB-encoded colour, in linear light.
inline glm::vec3 chroma_of_srgb(glm::vec3 c) {
  const glm::vec3 l(srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b));
  return l / (l.r + l.g + l.b);
}

inline glm::vec3 chroma(glm::vec3 c) { return c / (c.r + c.g + c.b); }

}  // namespace ms::test
