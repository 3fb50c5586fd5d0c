// render/environment.h: the equirectangular directions and the irradiance
// coefficients against what they must give (a constant map, a half-space).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include <glm/geometric.hpp>

#include "files.h"
#include "io/image_io.h"
#include "render/environment.h"

namespace ms {
namespace {

Image map_of(int w, int h, float (*radiance)(glm::vec3)) {
  Image m;
  m.width = w;
  m.height = h;
  m.channels = {"R", "G", "B"};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = radiance(equirect_direction(x + 0.5, y + 0.5, w, h));
      m.pixels.insert(m.pixels.end(), {v, v, v});
    }
  return m;
}

TEST(Environment, EquirectDirections) {
  const glm::vec3 centre = equirect_direction(32, 16, 64, 32), up = equirect_direction(10, 0, 64, 32);
  EXPECT_NEAR(centre.z, 1.0f, 1e-6f);
  EXPECT_NEAR(up.y, 1.0f, 1e-6f);
  EXPECT_NEAR(equirect_direction(48, 16, 64, 32).x, 1.0f, 1e-6f);  // u grows towards +x
  EXPECT_NEAR(equirect_direction(0, 16, 64, 32).z, -1.0f, 1e-6f);
}

TEST(Environment, ConstantMapGivesItsRadianceEverywhere) {
  const IrradianceSh sh = irradiance_sh(map_of(128, 64, [](glm::vec3) { return 2.0f; }));
  for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1),
                            glm::normalize(glm::vec3(1, 1, 1))})
    EXPECT_NEAR(eval_irradiance(sh, n).x, 2.0f, 2e-3f) << n.x << "," << n.y << "," << n.z;
}

// Light from the upper half only: E/pi is 1 facing up, 0 facing down and
// 1/2 sideways; band 2 gets within a few percent of that.
TEST(Environment, UpperHalfSpaceFollowsTheCosineLobe) {
  const IrradianceSh sh = irradiance_sh(map_of(256, 128, [](glm::vec3 d) { return d.y > 0.0f ? 1.0f : 0.0f; }));
  EXPECT_NEAR(eval_irradiance(sh, {0, 1, 0}).x, 1.0f, 0.08f);
  EXPECT_NEAR(eval_irradiance(sh, {0, -1, 0}).x, 0.0f, 0.08f);
  EXPECT_NEAR(eval_irradiance(sh, {1, 0, 0}).x, 0.5f, 0.02f);
  EXPECT_NEAR(eval_irradiance(sh, {0, 0, 1}).x, 0.5f, 0.02f);
}

// The viewer prepares a reload on every save: an unchanged map is not read
// and decoded again (the same image object), a changed one is.
TEST(Environment, AnUnchangedMapIsNotReadAgain) {
  namespace fs = std::filesystem;
  const test::TempDir tmp;
  const fs::path dir = tmp.path();
  setenv("XDG_CACHE_HOME", (dir / "cache").c_str(), 1);  // the irradiance cache, not the user's
  const fs::path file = dir / "sky.exr";
  write_image(map_of(16, 8, [](glm::vec3) { return 1.0f; }), file);
  Scene scene;
  scene.sky.environment = file;
  PassSource a, b, c;
  bool from_cache = false;
  attach_environment(scene, a, &from_cache);
  attach_environment(scene, b, &from_cache);
  EXPECT_EQ(a.inputs[0].image, b.inputs[0].image) << "the same file was decoded twice";
  EXPECT_TRUE(from_cache);
  write_image(map_of(16, 8, [](glm::vec3) { return 2.0f; }), file);
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));  // past any timestamp granularity
  attach_environment(scene, c, &from_cache);
  ASSERT_NE(c.inputs[0].image, a.inputs[0].image) << "a changed file was not read again";
  EXPECT_NEAR(c.inputs[0].image->pixels[0], 2.0f, 1e-6f);
  EXPECT_NEAR(eval_irradiance(scene.sky.irradiance, glm::vec3(0, 1, 0)).x, 2.0f, 0.05f);  // the new map lights (the old: 1)
  unsetenv("XDG_CACHE_HOME");
}

}  // namespace
}  // namespace ms
