// --set beats the scene file's [[animation]] (scene/overrides.h): the track
// of an overridden value is dropped, so the set value holds at every time,
// and Scene::notes says which flag replaced which track (for -v).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene/animation.h"
#include "scene/load.h"
#include "scene/overrides.h"

namespace ms {
namespace {

const std::filesystem::path kFile = std::filesystem::path(MARCH_TEST_DATA) / "scene" / "inline.toml";

// The camera's fov and position, the ball's colour and the light animated.
constexpr const char* kScene =
    "[scene]\n"
    "map = \"seed.glsl\"\n"
    "[camera]\n"
    "fov = 45.0\n"
    "position = [0.0, 1.0, -5.0]\n"
    "[[lights]]\n"
    "intensity = 2.0\n"
    "[[materials]]\n"
    "name = \"floor\"\n"
    "[[materials]]\n"
    "name = \"ball\"\n"
    "[[animation]]\n"  // line 12
    "target = \"camera.fov\"\n"
    "keys = [[0.0, 45.0], [2.0, 90.0]]\n"
    "[[animation]]\n"  // line 15
    "target = \"camera.position\"\n"
    "keys = [[0.0, 0.0, 1.0, -5.0], [2.0, 3.0, 1.0, -4.0]]\n"
    "[[animation]]\n"  // line 18
    "target = \"materials[1].color\"\n"
    "keys = [[0.0, 1.0, 0.0, 0.0], [2.0, 0.0, 0.0, 1.0]]\n"
    "[[animation]]\n"  // line 21
    "target = \"lights[0].intensity\"\n"
    "keys = [[0.0, 1.0], [2.0, 3.0]]\n";

KeyStep key(const char* k) { return {k, 0, false}; }
KeyStep at(std::size_t i) { return {{}, i, true}; }

template <class V>
SceneOverride set(std::string flag, std::vector<KeyStep> path, V value) {
  SceneOverride o;
  o.flag = "--set " + flag;
  o.path = std::move(path);
  o.value.push_back(std::move(value));
  return o;
}

bool animates(const Scene& s, const std::string& target) {
  for (const AnimationTrack& t : s.animation)
    if (t.target == target) return true;
  return false;
}

TEST(SceneOverrideAnimation, SetWinsOverTheTrackAtEveryTime) {
  // Another key set: every track plays, nothing to note.
  const Scene other = parse_scene(kScene, kFile, {set("render.width", {key("render"), key("width")}, 100)});
  EXPECT_EQ(other.animation.size(), 4u);
  EXPECT_TRUE(other.notes.empty());
  EXPECT_FLOAT_EQ(animated(other, 2.0).camera.fov_deg, 90.0f);
  const Scene s = parse_scene(kScene, kFile, {set("camera.fov", {key("camera"), key("fov")}, 30.0)});
  EXPECT_FALSE(animates(s, "camera.fov"));
  for (double t : {0.0, 1.0, 2.0, 5.0}) EXPECT_FLOAT_EQ(animated(s, t).camera.fov_deg, 30.0f) << "at t=" << t;
  // The other tracks stay.
  EXPECT_TRUE(animates(s, "camera.position"));
  EXPECT_FLOAT_EQ(animated(s, 2.0).camera.position.x, 3.0f);
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_EQ(s.notes[0],
            "--set camera.fov replaces the [[animation]] of 'camera.fov' at line 12: the set value holds at every time");
}

TEST(SceneOverrideAnimation, AnEntryByNameOrIndex) {
  const Scene s = parse_scene(kScene, kFile,
                              {set("materials.ball.color", {key("materials"), key("ball"), key("color")},
                                   toml::array{0.0, 1.0, 0.0}),
                               set("lights[0].intensity", {key("lights"), at(0), key("intensity")}, 5.0)});
  EXPECT_FALSE(animates(s, "materials[1].color"));
  EXPECT_FALSE(animates(s, "lights[0].intensity"));
  const Scene later = animated(s, 2.0);
  EXPECT_FLOAT_EQ(later.materials[1].color.g, 1.0f);
  EXPECT_FLOAT_EQ(later.lights[0].intensity, 5.0f);
  EXPECT_EQ(s.notes.size(), 2u);
}

TEST(SceneOverrideAnimation, AnElementDropsItsVectorsTrackAndATableItsMembers) {
  Scene s = parse_scene(kScene, kFile, {set("camera.position[1]", {key("camera"), key("position"), at(1)}, 2.5)});
  EXPECT_FALSE(animates(s, "camera.position"));
  EXPECT_TRUE(animates(s, "camera.fov"));
  EXPECT_FLOAT_EQ(animated(s, 2.0).camera.position.y, 2.5f);
  EXPECT_FLOAT_EQ(animated(s, 2.0).camera.position.x, 0.0f);  // the file's static value, the track gone
  toml::table camera;
  camera.insert("fov", 50.0);
  camera.insert("position", toml::array{0.0, 1.0, -6.0});
  s = parse_scene(kScene, kFile, {set("camera", {key("camera")}, camera)});
  EXPECT_FALSE(animates(s, "camera.fov"));
  EXPECT_FALSE(animates(s, "camera.position"));
  EXPECT_TRUE(animates(s, "lights[0].intensity"));
}

}  // namespace
}  // namespace ms
