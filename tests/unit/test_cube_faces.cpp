// io/cube_faces.h: Shadertoy's face file names, the direction through a
// point of each face against GL's table, and the equirectangular
// conversion against directions the test computes.
#include <gtest/gtest.h>

#include <cmath>

#include "io/cube_faces.h"

namespace ms {
namespace {

TEST(CubeFaces, ShadertoysFaceFileNames) {
  const auto f = cube_face_files("/m/a/0123abcd.jpg");
  EXPECT_EQ(f[0], "/m/a/0123abcd.jpg");
  EXPECT_EQ(f[1], "/m/a/0123abcd_1.jpg");
  EXPECT_EQ(f[5], "/m/a/0123abcd_5.jpg");
}

TEST(CubeFaces, DirectionsFollowGlsTable) {
  const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int face = 0; face < 6; ++face) {
    float d[3];
    cube_face_direction(face, 0.5f, 0.5f, d);
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(d[k], axes[face][k]) << face;
  }
  // The first texel row and column (s = t = 0), as GL's table puts them:
  // +X (1, 1, 1), -X (-1, 1, -1), +Y (-1, 1, -1), -Y (-1, -1, 1), +Z (-1, 1, 1), -Z (1, 1, -1).
  const float corner[6][3] = {{1, 1, 1}, {-1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, -1}};
  const float r = 1.0f / std::sqrt(3.0f);
  for (int face = 0; face < 6; ++face) {
    float d[3];
    cube_face_direction(face, 0.0f, 0.0f, d);
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(d[k], corner[face][k] * r) << face << " " << k;
  }
}

TEST(CubeFaces, EquirectangularToFaces) {
  // Each pixel holds its own direction under the documented layout; every
  // face texel must then hold (nearly) the direction through it.
  const double pi = 3.14159265358979323846;
  Image eq;
  eq.width = 512;
  eq.height = 256;
  eq.channels = {"R", "G", "B"};
  for (int y = 0; y < eq.height; ++y)
    for (int x = 0; x < eq.width; ++x) {
      const double lon = 2 * pi * (x + 0.5) / eq.width, lat = pi * (0.5 - (y + 0.5) / eq.height);
      eq.pixels.insert(eq.pixels.end(), {static_cast<float>(-std::cos(lat) * std::sin(lon)),
                                         static_cast<float>(std::sin(lat)),
                                         static_cast<float>(std::cos(lat) * std::cos(lon))});
    }
  const CubeFaces c = equirect_to_cube(eq);
  EXPECT_EQ(c.size, 128);
  EXPECT_FALSE(c.eight_bit);
  double worst = 0;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < c.size; j += 7)
      for (int i = 0; i < c.size; i += 5) {
        float d[3];
        cube_face_direction(f, (i + 0.5f) / c.size, (j + 0.5f) / c.size, d);
        for (int k = 0; k < 3; ++k) {
          const double got = c.faces[f].pixels[(static_cast<size_t>(j) * c.size + i) * 4 + k];
          worst = std::max(worst, std::abs(got - d[k]));
        }
        EXPECT_EQ(c.faces[f].pixels[(static_cast<size_t>(j) * c.size + i) * 4 + 3], 1.0f);
      }
  // Bilinear on a 512x256 grid: within a few thousandths (the poles' rows included).
  EXPECT_LT(worst, 0.01);
  EXPECT_EQ(equirect_to_cube(eq, 16).size, 16);
}

}  // namespace
}  // namespace ms
