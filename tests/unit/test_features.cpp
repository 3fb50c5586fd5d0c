// FeatureSet (scene/features.h): what a scene uses, derived from the Scene
// and the names its GLSL references.
#include <gtest/gtest.h>

#include "scene/features.h"

namespace ms {
namespace {

Scene base_scene() {
  Scene s;
  Material floor;
  floor.name = "floor";
  Material ball;
  ball.name = "ball";
  s.materials = {floor, ball};
  s.lights.resize(1);  // one point light
  return s;            // quality defaults: shadows, AO, reflections on, 1 bounce
}

TEST(Features, LightsKeepTheirKindsInOrder) {
  Scene s = base_scene();
  s.lights.resize(3);
  s.lights[1].kind = LightKind::directional;
  const FeatureSet f = derive_features(s, "");
  ASSERT_EQ(f.lights.size(), 3u);
  EXPECT_EQ(f.lights[0], LightKind::point);
  EXPECT_EQ(f.lights[1], LightKind::directional);
  EXPECT_EQ(f.point_lights(), 2);
  EXPECT_EQ(f.directional_lights(), 1);
}

TEST(Features, ReflectiveNeedsAMirrorReflectionsAndABounce) {
  Scene s = base_scene();
  s.quality.bounces = 3;
  FeatureSet f = derive_features(s, "");
  EXPECT_FALSE(f.reflective) << "no material reflects";
  EXPECT_EQ(f.max_bounces, 0);
  s.materials[1].reflectivity = 0.2f;
  f = derive_features(s, "");
  EXPECT_TRUE(f.reflective);
  EXPECT_EQ(f.max_bounces, 3);
  s.quality.reflections = false;
  EXPECT_FALSE(derive_features(s, "").reflective);
  s.quality.reflections = true;
  s.quality.bounces = 0;
  EXPECT_FALSE(derive_features(s, "").reflective);
}

TEST(Features, AKeyframedReflectivityCounts) {
  Scene s = base_scene();
  AnimationTrack t;
  t.target = "materials[1].reflectivity";
  t.times = {0.0, 1.0};
  t.values = {0.0, 0.0};
  s.animation.push_back(t);
  EXPECT_FALSE(derive_features(s, "").reflective) << "keyed at 0 throughout";
  s.animation[0].values = {0.0, 0.5};
  EXPECT_TRUE(derive_features(s, "").reflective);
  s.animation[0].target = "materials[1].specular";  // another value does not
  EXPECT_FALSE(derive_features(s, "").reflective);
}

TEST(Features, ShadowsAoAndChecker) {
  Scene s = base_scene();
  FeatureSet f = derive_features(s, "");
  EXPECT_TRUE(f.shadows);
  EXPECT_TRUE(f.ao);
  EXPECT_FALSE(f.checker);
  s.quality.shadow_steps = 0;
  s.quality.ao_taps = 0;
  s.materials[0].pattern = Pattern::checker;
  f = derive_features(s, "");
  EXPECT_FALSE(f.shadows);
  EXPECT_FALSE(f.ao);
  EXPECT_TRUE(f.checker);
  s = base_scene();
  s.lights.clear();
  EXPECT_FALSE(derive_features(s, "").shadows) << "no light casts a shadow";
  s.quality.ao = false;
  EXPECT_FALSE(derive_features(s, "").ao);
}

TEST(Features, LibraryNamesAreScannedLexically) {
  const char* glsl =
      "// sdTorus in a comment does not count\n"
      "/* nor opRepeat\n in a block comment */\n"
      "float sdf = 1.0; float opacity = 0.5;   // lower case after the prefix: not library names\n"
      "vec2 map(vec3 p) {\n"
      "  float d = opSmoothUnion(sdBox(p, vec3(1.0)), sdSphere(p, 1.0), 0.1);\n"
      "  return vec2(opUnion(d, sdBox(p, vec3(2.0))), mySdCone(p));\n"
      "}\n";
  const std::vector<std::string> names = referenced_library_names(glsl);
  EXPECT_EQ(names, (std::vector<std::string>{"opSmoothUnion", "opUnion", "sdBox", "sdSphere"}));
  EXPECT_TRUE(referenced_library_names("").empty());
  EXPECT_EQ(referenced_library_names("sd2Box(p) /* unterminated"), std::vector<std::string>{"sd2Box"});
  // Every kind prefix: distances, unsigned distances, domain operators, noise.
  EXPECT_EQ(referenced_library_names("udTriangle(domTwist(p, k), a, b, c) + noiseFbm(p.xz, 4, 0.5) + "
                                     "ud2Segment(q, a, b) + domain + noisy + udder"),
            (std::vector<std::string>{"domTwist", "noiseFbm", "ud2Segment", "udTriangle"}));
}

TEST(Features, EqualScenesGiveEqualSetsAndDescribeSaysWhat) {
  Scene s = base_scene();
  s.materials[0].pattern = Pattern::checker;
  const FeatureSet a = derive_features(s, "sdSphere(p, 1.0)");
  const FeatureSet b = derive_features(s, std::vector<std::string>{"sdSphere"});
  EXPECT_EQ(a, b);
  s.materials[0].color = glm::vec3(0.1f);  // a value, not a feature
  EXPECT_EQ(derive_features(s, "sdSphere(p, 1.0)"), a);
  const std::string d = describe(a);
  for (const char* part : {"lights: point", "no reflections", "shadows", "ao", "checker", "uses: sdSphere"})
    EXPECT_NE(d.find(part), std::string::npos) << part << " in " << d;
}

}  // namespace
}  // namespace ms
