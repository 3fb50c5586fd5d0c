// Scene loading: valid files parse to exactly the values written, absent
// keys keep the struct defaults, and scene.map resolves next to the file.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/load.h"

namespace fs = std::filesystem;

namespace {

const fs::path kDir = fs::path(MARCH_TEST_DATA) / "scene";
const fs::path kInline = kDir / "inline.toml";  // never read; names errors and anchors map

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
  EXPECT_FLOAT_EQ(v.x, x);
  EXPECT_FLOAT_EQ(v.y, y);
  EXPECT_FLOAT_EQ(v.z, z);
}

void expect_vec3(const glm::vec3& v, const glm::vec3& w) { expect_vec3(v, w.x, w.y, w.z); }

constexpr const char* kMinimal =
    "[scene]\n"
    "map = \"seed.glsl\"\n"
    "[[materials]]\n"
    "name = \"floor\"\n";

TEST(SceneLoad, FullFileParsesToExactValues) {
  const ms::Scene s = ms::load_scene(kDir / "full.toml");
  EXPECT_EQ(s.file, kDir / "full.toml");
  EXPECT_EQ(s.map_file, kDir / "seed.glsl");
  EXPECT_EQ(s.name, "full test");

  expect_vec3(s.camera.position, 0.5f, 1.25f, -4.0f);
  expect_vec3(s.camera.target, 0.0f, 0.75f, 1.0f);
  expect_vec3(s.camera.up, 0.0f, 0.0f, 1.0f);
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 60.0f);

  EXPECT_EQ(s.render.width, 640);
  EXPECT_EQ(s.render.height, 360);
  EXPECT_EQ(s.render.spp, 4);
  EXPECT_FLOAT_EQ(s.render.time, 2.5f);
  EXPECT_FLOAT_EQ(s.render.exposure, 1.5f);
  EXPECT_EQ(s.render.tonemap, ms::Tonemap::reinhard);

  expect_vec3(s.sky.horizon, 0.5f, 0.6f, 0.7f);
  expect_vec3(s.sky.zenith, 0.1f, 0.2f, 0.3f);
  expect_vec3(s.sky.ambient, 0.05f, 0.06f, 0.07f);

  const ms::Quality& q = s.quality;
  EXPECT_EQ(q.max_steps, 128);
  EXPECT_FLOAT_EQ(q.max_distance, 50.0f);
  EXPECT_FLOAT_EQ(q.hit_tolerance, 0.25f);
  EXPECT_FLOAT_EQ(q.hit_epsilon, 1e-3f);
  EXPECT_FLOAT_EQ(q.lipschitz, 1.5f);
  EXPECT_EQ(q.shadow_steps, 32);
  EXPECT_EQ(q.ao_taps, 3);
  EXPECT_EQ(q.bounces, 2);
  EXPECT_FALSE(q.shadows);
  EXPECT_FALSE(q.ao);
  EXPECT_FALSE(q.reflections);
  EXPECT_FALSE(q.checker_filter);

  ASSERT_EQ(s.lights.size(), 2u);
  const ms::Light& p = s.lights[0];
  EXPECT_EQ(p.kind, ms::LightKind::point);
  expect_vec3(p.position, 2.0f, 4.0f, -2.0f);
  expect_vec3(p.color, 1.0f, 0.9f, 0.8f);
  EXPECT_FLOAT_EQ(p.intensity, 2.0f);
  EXPECT_FLOAT_EQ(p.size, 0.2f);
  expect_vec3(p.attenuation, 1.0f, 0.1f, 0.02f);
  const ms::Light& d = s.lights[1];
  EXPECT_EQ(d.kind, ms::LightKind::directional);
  expect_vec3(d.direction, -0.5f, -1.0f, 0.25f);  // stored as written; the host normalises
  expect_vec3(d.color, 0.5f, 0.5f, 0.5f);
  EXPECT_FLOAT_EQ(d.intensity, 0.75f);
  EXPECT_FLOAT_EQ(d.size, 0.53f);

  ASSERT_EQ(s.materials.size(), 2u);  // ids follow file order
  const ms::Material& m = s.materials[0];
  EXPECT_EQ(m.name, "floor");
  expect_vec3(m.color, 0.9f, 0.9f, 0.9f);
  EXPECT_FLOAT_EQ(m.ambient, 0.5f);
  EXPECT_FLOAT_EQ(m.diffuse, 0.75f);
  EXPECT_FLOAT_EQ(m.specular, 0.25f);
  EXPECT_FLOAT_EQ(m.shininess, 16.0f);
  EXPECT_FLOAT_EQ(m.reflectivity, 0.125f);
  EXPECT_EQ(m.pattern, ms::Pattern::checker);
  expect_vec3(m.color2, 0.2f, 0.3f, 0.4f);
  EXPECT_FLOAT_EQ(m.pattern_scale, 2.0f);
  expect_vec3(m.pattern_velocity, 0.0f, 0.0f, 1.5f);
  EXPECT_EQ(s.materials[1].name, "ball");
}

TEST(SceneLoad, AbsentKeysKeepDefaults) {
  const ms::Scene s = ms::parse_scene(kMinimal, kInline);
  EXPECT_EQ(s.name, "inline");  // the file stem
  EXPECT_TRUE(s.lights.empty());

  const ms::Camera c;
  expect_vec3(s.camera.position, c.position);
  expect_vec3(s.camera.target, c.target);
  expect_vec3(s.camera.up, c.up);
  EXPECT_EQ(s.camera.fov_deg, c.fov_deg);

  const ms::RenderSettings r;
  EXPECT_EQ(s.render.width, r.width);
  EXPECT_EQ(s.render.height, r.height);
  EXPECT_EQ(s.render.spp, r.spp);
  EXPECT_EQ(s.render.time, r.time);
  EXPECT_EQ(s.render.exposure, r.exposure);
  EXPECT_EQ(s.render.tonemap, r.tonemap);

  const ms::Sky k;
  expect_vec3(s.sky.horizon, k.horizon);
  expect_vec3(s.sky.zenith, k.zenith);
  expect_vec3(s.sky.ambient, k.ambient);

  const ms::Quality q;
  EXPECT_EQ(s.quality.max_steps, q.max_steps);
  EXPECT_EQ(s.quality.max_distance, q.max_distance);
  EXPECT_EQ(s.quality.hit_tolerance, q.hit_tolerance);
  EXPECT_EQ(s.quality.hit_epsilon, q.hit_epsilon);
  EXPECT_EQ(s.quality.lipschitz, q.lipschitz);
  EXPECT_EQ(s.quality.shadow_steps, q.shadow_steps);
  EXPECT_EQ(s.quality.ao_taps, q.ao_taps);
  EXPECT_EQ(s.quality.bounces, q.bounces);
  EXPECT_EQ(s.quality.shadows, q.shadows);
  EXPECT_EQ(s.quality.ao, q.ao);
  EXPECT_EQ(s.quality.reflections, q.reflections);
  EXPECT_EQ(s.quality.checker_filter, q.checker_filter);

  ASSERT_EQ(s.materials.size(), 1u);
  const ms::Material m;
  const ms::Material& got = s.materials[0];
  expect_vec3(got.color, m.color);
  EXPECT_EQ(got.ambient, m.ambient);
  EXPECT_EQ(got.diffuse, m.diffuse);
  EXPECT_EQ(got.specular, m.specular);
  EXPECT_EQ(got.shininess, m.shininess);
  EXPECT_EQ(got.reflectivity, m.reflectivity);
  EXPECT_EQ(got.pattern, m.pattern);
  expect_vec3(got.color2, m.color2);
  EXPECT_EQ(got.pattern_scale, m.pattern_scale);
  expect_vec3(got.pattern_velocity, m.pattern_velocity);
}

TEST(SceneLoad, LightDefaultsPerType) {
  const ms::Scene s = ms::parse_scene(std::string(kMinimal) +
                                          "[[lights]]\n"
                                          "[[lights]]\n"
                                          "type = \"directional\"\n",
                                      kInline);
  ASSERT_EQ(s.lights.size(), 2u);
  const ms::Light def;
  EXPECT_EQ(s.lights[0].kind, ms::LightKind::point);  // type defaults to point
  expect_vec3(s.lights[0].position, def.position);
  expect_vec3(s.lights[0].attenuation, def.attenuation);
  EXPECT_EQ(s.lights[1].kind, ms::LightKind::directional);
  expect_vec3(s.lights[1].direction, def.direction);
  EXPECT_EQ(s.lights[1].size, def.size);
}

TEST(SceneLoad, IntegersAcceptedForFloatsAndEdgesOfRanges) {
  const ms::Scene s = ms::parse_scene(std::string(kMinimal) +
                                          "[render]\nwidth = 16384\nheight = 1\nspp = 1024\nexposure = 2\n"
                                          "[quality]\nlipschitz = 1\nhit_tolerance = 0\nshadow_steps = 0\n"
                                          "ao_taps = 64\nbounces = 0\n"
                                          "[camera]\nfov = 179.5\nposition = [1, 2, 3]\n",
                                      kInline);
  EXPECT_EQ(s.render.width, 16384);
  EXPECT_EQ(s.render.height, 1);
  EXPECT_EQ(s.render.spp, 1024);
  EXPECT_FLOAT_EQ(s.render.exposure, 2.0f);
  EXPECT_FLOAT_EQ(s.quality.lipschitz, 1.0f);
  EXPECT_FLOAT_EQ(s.quality.hit_tolerance, 0.0f);
  EXPECT_EQ(s.quality.ao_taps, 64);
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 179.5f);
  expect_vec3(s.camera.position, 1.0f, 2.0f, 3.0f);
}

TEST(SceneLoad, DottedKeysAndInlineTablesAreTheSameTables) {
  const ms::Scene s = ms::parse_scene(
      "scene = { map = \"seed.glsl\", name = \"dotted\" }\n"
      "camera.fov = 30\n"
      "materials = [ { name = \"a\" }, { name = \"b\", pattern = \"checker\" } ]\n"
      "lights = [ { type = \"directional\", direction = [0, -1, 1] } ]\n",
      kInline);
  EXPECT_EQ(s.name, "dotted");
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 30.0f);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[1].pattern, ms::Pattern::checker);
  ASSERT_EQ(s.lights.size(), 1u);
  expect_vec3(s.lights[0].direction, 0.0f, -1.0f, 1.0f);
}

TEST(SceneLoad, MapResolvesRelativeToTheSceneFile) {
  const ms::Scene s = ms::load_scene(kDir / "nested" / "up.toml");
  EXPECT_EQ(s.map_file, kDir / "seed.glsl");  // "../seed.glsl", normalised
  EXPECT_TRUE(fs::exists(s.map_file));
  EXPECT_EQ(s.name, "up");
}

TEST(SceneLoad, AbsoluteMapPathIsKept) {
  const fs::path abs = fs::absolute(kDir / "seed.glsl");
  const ms::Scene s = ms::parse_scene(
      "[scene]\nmap = \"" + abs.generic_string() + "\"\n[[materials]]\nname = \"m\"\n",
      fs::path("/nonexistent/dir/x.toml"));
  EXPECT_EQ(s.map_file, abs.lexically_normal());
}

TEST(SceneLoad, FileIsThePathAsGiven) {
  // A relative path stays relative in Scene::file, and the map resolves
  // against it from the current directory.
  const fs::path rel = fs::relative(kDir / "full.toml");
  ASSERT_TRUE(rel.is_relative());
  const ms::Scene s = ms::load_scene(rel);
  EXPECT_EQ(s.file, rel);
  EXPECT_EQ(s.map_file, (rel.parent_path() / "seed.glsl").lexically_normal());
  EXPECT_TRUE(fs::exists(s.map_file));
}

TEST(SceneLoad, MaterialNamesAreCaseSensitiveButUniqueIgnoringCase) {
  const ms::Scene s = ms::parse_scene(
      "[scene]\nmap = \"seed.glsl\"\n"
      "[[materials]]\nname = \"Floor_2\"\n[[materials]]\nname = \"ball\"\n",
      kInline);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "Floor_2");  // kept as written; GLSL upper-cases
}

}  // namespace
