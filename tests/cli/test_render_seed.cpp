// The founding scene, end to end through the real binary: backends agree,
// output is deterministic, and the image shows what the scene says: the
// sphere's material at its centre, a cast shadow, a reflection under the
// sphere, and alternating checker cells.
#include <gtest/gtest.h>

#include <cmath>

#include "io/image_io.h"
#include "probe.h"
#include "run.h"
#include "scene/load.h"

namespace ms::test {
namespace {

constexpr int W = 320, H = 180;

Image render_seed(TempDir& dir, const std::string& name, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", (source_dir() / "scenes/seed.toml").string(), "-o",
                                   (dir / name).string(), "--size", std::to_string(W) + "x" + std::to_string(H)};
  args.insert(args.end(), extra.begin(), extra.end());
  RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, (dir / name).string() + "\n");  // prints the path it wrote
  return read_image(dir / name);
}

struct Diff {
  double mean = 0, max = 0;
};

Diff diff(const Image& a, const Image& b) {
  Diff d;
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i) {
    const double e = std::abs(a.pixels[i] - b.pixels[i]);
    d.mean += e;
    d.max = std::max(d.max, e);
  }
  d.mean /= static_cast<double>(a.pixels.size());
  return d;
}

class Seed : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(load_scene(source_dir() / "scenes/seed.toml")); }
  static void TearDownTestSuite() { delete scene_; }
  static Scene* scene_;
  TempDir dir;

  // The seed scene's layout: sphere (centre 0,1,0; radius 1) on the plane y = 0.
  const glm::vec3 centre{0.0f, 1.0f, 0.0f};
  const Material& sphere_mat() const { return scene_->materials.at(1); }
  const Material& floor_mat() const { return scene_->materials.at(0); }
  PixelPos px(glm::vec3 p) const { return project(scene_->camera, W, H, p); }
};
Scene* Seed::scene_ = nullptr;

TEST_F(Seed, EglAndOsmesaAgree) {
  Image egl = render_seed(dir, "egl.png", {"--backend", "egl"});
  Image osm = render_seed(dir, "osmesa.png", {"--backend", "osmesa"});
  Diff d = diff(egl, osm);
  // Both are llvmpipe here; allow one 8-bit step anywhere for driver differences.
  EXPECT_LE(d.max, 1.0 / 255.0 + 1e-6);
  EXPECT_LE(d.mean, 0.1 / 255.0);
}

TEST_F(Seed, Deterministic) {
  Image a = render_seed(dir, "a.png"), b = render_seed(dir, "b.png");
  Diff d = diff(a, b);
  EXPECT_EQ(d.max, 0.0);
}

TEST_F(Seed, SphereCentreShowsTheSphereMaterial) {
  ASSERT_EQ(scene_->materials.size(), 2u);
  Image img = render_seed(dir, "seed.png");
  // The sphere's centre as seen by the camera: its chromaticity (linear
  // light) is nearer the sphere material's than the floor's.
  const glm::vec3 c = chroma_of_srgb(mean_rgb(img, px(centre), 1));
  const float to_sphere = glm::length(c - chroma(sphere_mat().color));
  const float to_floor = glm::length(c - chroma(floor_mat().color));
  EXPECT_LT(to_sphere, to_floor) << c.r << "," << c.g << "," << c.b;
}

TEST_F(Seed, CastShadowIsDarkerThanTheSameCellLit) {
  ASSERT_FALSE(scene_->lights.empty());
  const Light& light = scene_->lights[0];
  ASSERT_EQ(light.kind, LightKind::point);
  // Walk away from the contact point, along the shadow's axis (the line
  // where the light's ray through the centre meets the floor), to the first
  // floor point deep in the umbra that the camera sees past the sphere.
  const glm::vec3 L = light.position, cam = scene_->camera.position;
  const glm::vec3 S = L + (centre - L) * (L.y / (L.y - centre.y));
  const glm::vec3 contact(centre.x, 0.0f, centre.z);
  glm::vec3 P(0.0f);
  bool found = false;
  for (float k = 1.0f; k < 4.0f && !found; k += 0.05f) {
    P = contact + k * (S - contact);
    const bool umbra = segment_near(P, L, centre, 1.0f - 0.4f);  // light radius 0.4 stays blocked
    const bool visible = !segment_near(cam, P, centre, 1.02f);
    found = umbra && visible;
  }
  ASSERT_TRUE(found) << "no visible umbra point";
  const PixelPos p = px(P);
  ASSERT_TRUE(p.x >= 2 && p.y >= 2 && p.x < W - 2 && p.y < H - 2) << "shadow point off screen";
  // EXR: linear radiance before the tone map, where shading ratios mean something.
  Image lit = render_seed(dir, "noshadow.exr", {"--disable", "shadows"});
  Image shadowed = render_seed(dir, "seed.exr");
  const float in_shadow = luma(mean_rgb(shadowed, p, 1));
  const float in_open = luma(mean_rgb(lit, p, 1));  // same point, same checker colour, light unblocked
  EXPECT_LT(in_shadow, 0.7f * in_open) << in_shadow << " vs " << in_open << " at (" << P.x << "," << P.z
                                        << ") pixel " << p.x << "," << p.y;
}

TEST_F(Seed, PlaneUnderTheSphereReflectsIt) {
  Image with = render_seed(dir, "seed.png");
  Image without = render_seed(dir, "norefl.png", {"--disable", "reflections"});
  // A floor point just in front of the sphere's base, towards the camera.
  glm::vec3 to_cam = scene_->camera.position - centre;
  to_cam.y = 0.0f;
  const glm::vec3 front = glm::vec3(centre.x, 0.0f, centre.z) + glm::normalize(to_cam) * 1.15f;
  const glm::vec3 a = mean_rgb(with, px(front), 2), b = mean_rgb(without, px(front), 2);
  EXPECT_GT(glm::length(a - b), 0.03f) << "reflection left the floor unchanged";
  // The sky far above is the same in both.
  const PixelPos sky{W / 2, 2};
  EXPECT_LT(glm::length(rgb(with, sky) - rgb(without, sky)), 1e-6f);
}

TEST_F(Seed, CheckerCellsAlternate) {
  const float c = floor_mat().pattern_scale;
  Image img = render_seed(dir, "flat.exr", {"--disable", "shadows,reflections,ao"});  // linear
  // Four neighbouring cell centres in a row between the camera and the sphere.
  const glm::vec3 cam = scene_->camera.position;
  const float z0 = (std::floor((cam.z + 0.6f * (centre.z - cam.z)) / c) + 0.5f) * c;
  const float x0 = (std::floor(cam.x / c) - 1.5f) * c;
  std::vector<float> l;
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 q(x0 + i * c, 0.0f, z0);
    ASSERT_FALSE(segment_near(cam, q, centre, 1.0f)) << "cell " << i << " hidden by the sphere";
    const PixelPos p = px(q);
    ASSERT_TRUE(p.x >= 1 && p.y >= 1 && p.x < W - 1 && p.y < H - 1) << "cell " << i << " off screen";
    l.push_back(luma(mean_rgb(img, p, 1)));
  }
  const bool up_first = l[0] > l[1];
  for (int i = 0; i < 3; ++i) {
    const float hi = std::max(l[i], l[i + 1]), lo = std::min(l[i], l[i + 1]);
    // The cell albedos differ 2.7x; lighting varies little between neighbours.
    EXPECT_GT(hi, 1.5f * lo) << "cells " << i << "," << i + 1 << ": " << l[i] << " " << l[i + 1];
    EXPECT_EQ(l[i] > l[i + 1], (i % 2 == 0) == up_first) << "cell " << i;
  }
}

}  // namespace
}  // namespace ms::test
