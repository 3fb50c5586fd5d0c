// Keyframe animation: [[animation]] tables parse to exact keys, evaluate to
// exact numbers (linear and smoothstep-eased, held outside the keys), apply
// to the scene, and every mistake is a file:line:key error.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/animation.h"
#include "scene/load.h"

namespace fs = std::filesystem;

namespace {

const fs::path kInline = fs::path(MARCH_TEST_DATA) / "scene" / "inline.toml";

// Lines 1-9; a case's body starts on line 10.
constexpr const char* kBase =
    "[scene]\n"
    "map = \"seed.glsl\"\n"
    "[[lights]]\n"
    "intensity = 1.0\n"
    "[[materials]]\n"
    "name = \"floor\"\n"
    "[[materials]]\n"
    "name = \"ball\"\n"
    "# body\n";

ms::Scene parse(const std::string& body) { return ms::parse_scene(kBase + body, kInline); }

ms::ErrorInfo error_of(const std::string& body) {
  try {
    parse(body);
  } catch (const ms::Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for:\n" << body;
  return {};
}

TEST(Animation, TracksParseToExactKeys) {
  const ms::Scene s = parse(
      "[[animation]]\n"
      "target = \"camera.position\"\n"
      "interpolation = \"smooth\"\n"
      "keys = [[0.0, 0.0, 1.6, -5.0], [2, 3.0, 1.6, -4.0]]\n"
      "[[animation]]\n"
      "target = \"materials[1].color\"\n"
      "keys = [[0.0, 1.0, 0.0, 0.0]]\n");
  ASSERT_EQ(s.animation.size(), 2u);
  const ms::AnimationTrack& cam = s.animation[0];
  EXPECT_EQ(cam.target, "camera.position");
  EXPECT_EQ(cam.interpolation, ms::Interpolation::smooth);
  EXPECT_EQ(cam.arity, 3);
  EXPECT_EQ(cam.times, (std::vector<double>{0.0, 2.0}));
  EXPECT_EQ(cam.values, (std::vector<double>{0.0, 1.6, -5.0, 3.0, 1.6, -4.0}));
  EXPECT_EQ(cam.line, 10);
  EXPECT_EQ(s.animation[1].interpolation, ms::Interpolation::linear) << "linear is the default";
  EXPECT_EQ(s.animation[1].times.size(), 1u);
}

TEST(Animation, LinearValuesAreExact) {
  ms::AnimationTrack t;
  t.arity = 1;
  t.times = {0.0, 2.0, 4.0};
  t.values = {0.0, 3.0, 1.0};
  EXPECT_EQ(ms::evaluate(t, -1.0)[0], 0.0) << "held before the first key";
  EXPECT_EQ(ms::evaluate(t, 0.0)[0], 0.0);
  EXPECT_EQ(ms::evaluate(t, 0.5)[0], 0.75);
  EXPECT_EQ(ms::evaluate(t, 1.0)[0], 1.5);
  EXPECT_EQ(ms::evaluate(t, 2.0)[0], 3.0) << "exactly the key";
  EXPECT_EQ(ms::evaluate(t, 3.0)[0], 2.0);
  EXPECT_EQ(ms::evaluate(t, 4.0)[0], 1.0);
  EXPECT_EQ(ms::evaluate(t, 100.0)[0], 1.0) << "held after the last key";
}

TEST(Animation, SmoothIsSmoothstepEased) {
  ms::AnimationTrack t;
  t.arity = 3;
  t.interpolation = ms::Interpolation::smooth;
  t.times = {0.0, 4.0};
  t.values = {0.0, 10.0, -8.0, 8.0, 10.0, 8.0};
  // u = 0.25: 0.25^2 * (3 - 0.5) = 0.15625; u = 0.5: 0.5; u = 0.75: 0.84375.
  auto v = ms::evaluate(t, 1.0);
  EXPECT_EQ(v[0], 1.25);
  EXPECT_EQ(v[1], 10.0);
  EXPECT_EQ(v[2], -5.5);
  v = ms::evaluate(t, 2.0);
  EXPECT_EQ(v[0], 4.0);
  EXPECT_EQ(v[2], 0.0);
  EXPECT_EQ(ms::evaluate(t, 3.0)[0], 6.75);
}

TEST(Animation, AnimatedSceneTakesTheValuesAtThatTime) {
  const ms::Scene s = parse(
      "[[animation]]\n"
      "target = \"camera.fov\"\n"
      "keys = [[0, 30], [1, 60]]\n"
      "[[animation]]\n"
      "target = \"lights[0].intensity\"\n"
      "keys = [[0, 0], [1, 2]]\n"
      "[[animation]]\n"
      "target = \"materials[1].color\"\n"
      "keys = [[0, 1, 0, 0], [1, 0, 0, 1]]\n"
      "[[animation]]\n"
      "target = \"render.exposure\"\n"
      "keys = [[0, 1], [1, 3]]\n");
  const ms::Scene a = ms::animated(s, 0.5);
  EXPECT_EQ(a.camera.fov_deg, 45.0f);
  EXPECT_EQ(a.lights[0].intensity, 1.0f);
  EXPECT_EQ(a.materials[1].color, glm::vec3(0.5f, 0.0f, 0.5f));
  EXPECT_EQ(a.render.exposure, 2.0f);
  EXPECT_EQ(s.camera.fov_deg, 45.0f) << "the static default (45) stays in the loaded scene";
  EXPECT_EQ(ms::animated(s, 0.25).camera.fov_deg, 37.5f);
}

TEST(Animation, DegeneratePoseAtSomeTimeIsAnError) {
  // The camera passes through its target at t = 1.
  const ms::Scene s = parse(
      "[camera]\n"
      "target = [0, 0, 0]\n"
      "[[animation]]\n"
      "target = \"camera.position\"\n"
      "keys = [[0, -1, 0, -1], [2, 1, 0, 1]]\n");
  EXPECT_NO_THROW(ms::animated(s, 0.5));
  try {
    ms::animated(s, 1.0);
    FAIL() << "no error";
  } catch (const ms::Error& e) {
    EXPECT_EQ(e.code(), ms::Exit::bad_input);
    EXPECT_EQ(e.info().line, 12);
    EXPECT_EQ(e.info().key, "animation[0]");
    EXPECT_NE(e.info().what.find("t=1 s"), std::string::npos) << e.what();
  }
}

struct Case {
  const char* name;
  std::string body;
  int line;
  std::string key;
  std::string what;  // substring of ErrorInfo::what
};

class AnimationError : public ::testing::TestWithParam<Case> {};

TEST_P(AnimationError, NamesLineKeyAndProblem) {
  const Case& c = GetParam();
  const ms::ErrorInfo e = error_of(c.body);
  EXPECT_EQ(e.code, ms::Exit::bad_input);
  EXPECT_EQ(e.file, kInline.string());
  EXPECT_EQ(e.line, c.line) << ms::format_error(e);
  EXPECT_EQ(e.key, c.key) << ms::format_error(e);
  EXPECT_NE(e.what.find(c.what), std::string::npos) << "what: " << e.what;
  EXPECT_EQ(ms::format_error(e).find('\n'), std::string::npos);
}

const std::string kAnim = "[[animation]]\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, AnimationError,
    ::testing::Values(
        Case{"UnknownObject", kAnim + "target = \"camra.fov\"\nkeys = [[0, 1]]\n", 11, "animation[0].target",
             "unknown animation target 'camra.fov'"},
        Case{"UnknownKey", kAnim + "target = \"camera.fvo\"\nkeys = [[0, 1]]\n", 11, "animation[0].target",
             "'fvo' cannot be animated on camera"},
        Case{"NoSuchLight", kAnim + "target = \"lights[3].intensity\"\nkeys = [[0, 1]]\n", 11,
             "animation[0].target", "the scene has 1 light"},
        Case{"IgnoredByLightType", kAnim + "target = \"lights[0].direction\"\nkeys = [[0, 1, 0, 0]]\n", 11,
             "animation[0].target", "does nothing for a point light"},
        Case{"MissingTarget", kAnim + "keys = [[0, 1]]\n", 10, "animation[0].target", "missing required key"},
        Case{"UnknownTableKey", kAnim + "target = \"camera.fov\"\nkyes = [[0, 1]]\n", 12, "animation[0].kyes",
             "unknown key"},
        Case{"BadInterpolation", kAnim + "target = \"camera.fov\"\ninterpolation = \"cubic\"\nkeys = [[0, 1]]\n",
             12, "animation[0].interpolation", "unknown value 'cubic'"},
        Case{"MissingKeys", kAnim + "target = \"camera.fov\"\n", 10, "animation[0].keys", "missing required key"},
        Case{"EmptyKeys", kAnim + "target = \"camera.fov\"\nkeys = []\n", 12, "animation[0].keys", "non-empty"},
        Case{"WrongArity", kAnim + "target = \"camera.position\"\nkeys = [[0, 1, 2, 3],\n  [1, 1, 2]]\n", 13,
             "animation[0].keys[1]", "must be 4 numbers (a time and 3 values for camera.position), got 3"},
        Case{"RowNotArray", kAnim + "target = \"camera.fov\"\nkeys = [1, 2]\n", 12, "animation[0].keys[0]",
             "must be 2 numbers"},
        Case{"Unsorted", kAnim + "target = \"camera.fov\"\nkeys = [[1, 40],\n [0.5, 50]]\n", 13,
             "animation[0].keys[1]", "time 0.5 comes before the previous key's 1"},
        Case{"DuplicateTime", kAnim + "target = \"camera.fov\"\nkeys = [[1, 40], [1, 50]]\n", 12,
             "animation[0].keys[1]", "repeats time 1"},
        Case{"NanValue", kAnim + "target = \"camera.fov\"\nkeys = [[0, nan]]\n", 12, "animation[0].keys[0][1]",
             "must be a finite number, got nan"},
        Case{"NanTime", kAnim + "target = \"camera.fov\"\nkeys = [[inf, 40]]\n", 12, "animation[0].keys[0][0]",
             "must be a finite number"},
        Case{"OutOfRange", kAnim + "target = \"camera.fov\"\nkeys = [[0, 40], [1, 180]]\n", 12,
             "animation[0].keys[1][1]", "must be in (0, 180), got 180"},
        Case{"NotANumber", kAnim + "target = \"lights[0].intensity\"\nkeys = [[0, \"1\"]]\n", 12,
             "animation[0].keys[0][1]", "must be a number"},
        Case{"Twice", kAnim + "target = \"camera.fov\"\nkeys = [[0, 40]]\n" + kAnim +
                          "target = \"camera.fov\"\nkeys = [[0, 50]]\n",
             14, "animation[1].target", "already animated by animation[0]"}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
