// --set overrides (scene/overrides.h) applied to a scene file's TOML before
// validation, and --uniform values (shader/scene_params.h) made the
// initializers of ranged uniforms. The flags' own parsing is tested through
// the binary (tests/cli/test_overrides.cpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/load.h"
#include "scene/overrides.h"
#include "shader/scene_params.h"

namespace fs = std::filesystem;

namespace ms {
namespace {

const fs::path kFile = fs::path(MARCH_TEST_DATA) / "scene" / "inline.toml";

// Lines 1-14.
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
    "color = [0.8, 0.1, 0.1]\n"
    "[render]\n"
    "width = 320\n";

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

ErrorInfo error_of(const SceneOverrides& ov, const std::string& text = kScene) {
  try {
    parse_scene(text, kFile, ov);
  } catch (const Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(SceneOverrides, SetAValueInATable) {
  const Scene s = parse_scene(kScene, kFile, {set("camera.fov", {key("camera"), key("fov")}, 30.0)});
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 30.0f);
  EXPECT_FLOAT_EQ(s.camera.position.z, -5.0f);  // the rest of the table is the file's
}

TEST(SceneOverrides, AnIntegerWhereTheFileHasAFloat) {
  // TOML's 30 is an integer; the scene's number fields take either, as in the file.
  const Scene s = parse_scene(kScene, kFile, {set("camera.fov", {key("camera"), key("fov")}, 30)});
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 30.0f);
}

TEST(SceneOverrides, AMissingTableIsCreated) {
  const Scene s = parse_scene(kScene, kFile, {set("quality.max_steps", {key("quality"), key("max_steps")}, 64)});
  EXPECT_EQ(s.quality.max_steps, 64);
  ASSERT_EQ(s.quality.explicit_keys.size(), 1u);  // as if the file said it: --preset keeps it
  EXPECT_EQ(s.quality.explicit_keys[0], "max_steps");
}

TEST(SceneOverrides, AMaterialByNameAndALightByIndex) {
  const Scene s = parse_scene(kScene, kFile,
                              {set("materials.ball.color", {key("materials"), key("ball"), key("color")},
                                   toml::array{0.0, 1.0, 0.0}),
                               set("lights[0].intensity", {key("lights"), at(0), key("intensity")}, 3.0)});
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_FLOAT_EQ(s.materials[1].color.g, 1.0f);
  EXPECT_FLOAT_EQ(s.materials[1].color.r, 0.0f);
  EXPECT_FLOAT_EQ(s.materials[0].color.g, 0.8f);  // floor keeps the default
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 3.0f);
}

TEST(SceneOverrides, AnElementOfAValueArray) {
  const Scene s = parse_scene(kScene, kFile, {set("camera.position[1]", {key("camera"), key("position"), at(1)}, 2.5)});
  EXPECT_FLOAT_EQ(s.camera.position.y, 2.5f);
  EXPECT_FLOAT_EQ(s.camera.position.z, -5.0f);
}

TEST(SceneOverrides, TheLastOfTheSameKeyWins) {
  const Scene s = parse_scene(kScene, kFile,
                              {set("render.width", {key("render"), key("width")}, 100),
                               set("render.width", {key("render"), key("width")}, 200)});
  EXPECT_EQ(s.render.width, 200);
}

TEST(SceneOverrides, AnUnknownKeyIsBlamedOnTheFlagWithAHint) {
  const ErrorInfo e = error_of({set("camera.fvo", {key("camera"), key("fvo")}, 30.0)});
  EXPECT_EQ(e.code, Exit::bad_input);
  EXPECT_EQ(e.file, "");  // not a line of the file: the flag
  EXPECT_EQ(e.line, 0);
  EXPECT_EQ(e.key, "--set camera.fvo");
  EXPECT_NE(e.what.find("unknown key 'camera.fvo'"), std::string::npos) << e.what;
  EXPECT_EQ(e.hint, "did you mean 'fov'?");
  EXPECT_EQ(format_error(e), "--set camera.fvo: unknown key 'camera.fvo' (did you mean 'fov'?)");
}

TEST(SceneOverrides, AnUnknownTableIsBlamedOnTheFlag) {
  const ErrorInfo e = error_of({set("camear.fov", {key("camear"), key("fov")}, 30.0)});
  EXPECT_EQ(e.key, "--set camear.fov");
  EXPECT_EQ(e.hint, "did you mean 'camera'?");
}

TEST(SceneOverrides, TheFilesOwnChecksApply) {
  const ErrorInfo nan = error_of({set("camera.fov", {key("camera"), key("fov")}, std::nan(""))});
  EXPECT_EQ(nan.key, "--set camera.fov");
  EXPECT_NE(nan.what.find("finite"), std::string::npos) << nan.what;
  const ErrorInfo type = error_of({set("camera.fov", {key("camera"), key("fov")}, std::string("wide"))});
  EXPECT_EQ(type.key, "--set camera.fov");
  EXPECT_NE(type.what.find("must be a number, not a string"), std::string::npos) << type.what;
  const ErrorInfo range = error_of({set("camera.fov", {key("camera"), key("fov")}, 180.0)});
  EXPECT_NE(range.what.find("in (0, 180)"), std::string::npos) << range.what;
  const ErrorInfo preset = error_of({set("quality.preset", {key("quality"), key("preset")}, std::string("fsat"))});
  EXPECT_EQ(preset.key, "--set quality.preset");
  EXPECT_EQ(preset.hint, "did you mean 'fast'?");
}

TEST(SceneOverrides, AMissingMaterialNameListsTheNames) {
  const ErrorInfo e = error_of({set("materials.bal.color", {key("materials"), key("bal"), key("color")},
                                    toml::array{1.0, 0.0, 0.0})});
  EXPECT_EQ(e.key, "--set materials.bal.color");
  EXPECT_NE(e.what.find("named 'bal'"), std::string::npos) << e.what;
  EXPECT_NE(e.hint.find("did you mean 'ball'?"), std::string::npos) << e.hint;
  EXPECT_NE(e.hint.find("floor, ball"), std::string::npos) << e.hint;
}

TEST(SceneOverrides, PathsThatLeadNowhereAreErrors) {
  const ErrorInfo past = error_of({set("lights[1].intensity", {key("lights"), at(1), key("intensity")}, 1.0)});
  EXPECT_EQ(past.key, "--set lights[1].intensity");
  EXPECT_NE(past.what.find("has 1 entry"), std::string::npos) << past.what;
  const ErrorInfo into_number = error_of({set("camera.fov.x", {key("camera"), key("fov"), key("x")}, 1.0)});
  EXPECT_NE(into_number.what.find("'camera.fov' is a float, not a table"), std::string::npos) << into_number.what;
  const ErrorInfo nothing = error_of({set("planes[0].offset", {key("planes"), at(0), key("offset")}, 1.0)});
  EXPECT_NE(nothing.what.find("'planes' is not in the scene"), std::string::npos) << nothing.what;
}

TEST(SceneOverrides, AnErrorOfTheFileStillNamesItsLine) {
  // The override is fine; the file's own mistake keeps its file:line.
  const ErrorInfo e = error_of({set("camera.fov", {key("camera"), key("fov")}, 30.0)}, std::string(kScene) + "spp = 0\n");
  EXPECT_EQ(e.file, kFile.string());
  EXPECT_EQ(e.line, 15);
  EXPECT_EQ(e.key, "render.spp");
}

TEST(UniformDefaults, AValueBecomesTheInitializer) {
  std::string glsl =
      "#line 1 1\n"
      "uniform float uTwist = 0.5;   // range(0, 2)\n"
      "  uniform vec3 uTint = vec3(1.0, 0.8, 0.6); // color\n"
      "uniform int uCount; // range(1, 16)\n"
      "float f() { return uTwist; }\n";
  const std::vector<bool> found =
      set_uniform_defaults(glsl, {{"uTwist", {1.25}}, {"uTint", {0.0, 0.5, 1.0}}, {"uCount", {7}}, {"uNone", {1}}});
  EXPECT_EQ(found, (std::vector<bool>{true, true, true, false}));
  EXPECT_NE(glsl.find("uniform float uTwist = 1.25;  // range(0, 2)\n"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("  uniform vec3 uTint = vec3(0.0, 0.5, 1.0);  // color\n"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("uniform int uCount = 7;  // range(1, 16)\n"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("float f() { return uTwist; }\n"), std::string::npos);
  // One line for one: #line numbering still holds.
  EXPECT_EQ(std::count(glsl.begin(), glsl.end(), '\n'), 5);
  // And the viewer's sliders start there.
  const std::vector<SceneParam> params = parse_scene_params(glsl);
  ASSERT_EQ(params.size(), 3u);
  EXPECT_FLOAT_EQ(params[0].initial[0], 1.25f);
  EXPECT_FLOAT_EQ(params[1].initial[2], 1.0f);
  EXPECT_FLOAT_EQ(params[2].initial[0], 7.0f);
}

TEST(UniformDefaults, AFloatLiteralParsesBackExactly) {
  std::string glsl = "uniform float uR = 1.0; // range(0.5, 2.0)\n";
  set_uniform_defaults(glsl, {{"uR", {1.3}}});
  EXPECT_NE(glsl.find("uR = 1.3;"), std::string::npos) << glsl;  // 1.3f's shortest round-trip digits
}

ErrorInfo uniform_error(const std::string& decl, const UniformValue& v) {
  std::string glsl = decl;
  try {
    set_uniform_defaults(glsl, {v});
  } catch (const Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for " << v.name;
  return {};
}

TEST(UniformDefaults, TypeCountAndRangeAreChecked) {
  const ErrorInfo range = uniform_error("uniform float uTwist = 0.5; // range(0, 2)\n", {"uTwist", {2.5}});
  EXPECT_EQ(range.code, Exit::bad_input);
  EXPECT_EQ(range.key, "--uniform uTwist");
  EXPECT_NE(range.what.find("outside the range [0, 2]"), std::string::npos) << range.what;
  const ErrorInfo count = uniform_error("uniform vec3 uTint = vec3(1.0); // color\n", {"uTint", {0.5}});
  EXPECT_NE(count.what.find("takes 3 numbers, got 1"), std::string::npos) << count.what;
  const ErrorInfo whole = uniform_error("uniform int uCount = 4; // range(1, 16)\n", {"uCount", {2.5}});
  EXPECT_NE(whole.what.find("whole number"), std::string::npos) << whole.what;
  const ErrorInfo colour = uniform_error("uniform vec3 uTint = vec3(1.0); // color\n", {"uTint", {0.5, 0.5, 1.5}});
  EXPECT_NE(colour.what.find("outside the range [0, 1]"), std::string::npos) << colour.what;
}

TEST(UniformDefaults, AnUnknownNameListsTheDeclaredOnes) {
  const std::vector<SceneParam> declared =
      parse_scene_params("uniform float uTwist = 0.5; // range(0, 2)\nuniform int uCount = 4; // range(1, 16)\n");
  try {
    check_uniforms_found({{"uTwsit", {1.0}}}, {false}, declared);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().key, "--uniform uTwsit");
    EXPECT_EQ(e.info().hint, "did you mean 'uTwist'? declared: uTwist, uCount");
  }
  EXPECT_NO_THROW(check_uniforms_found({{"uTwist", {1.0}}}, {true}, declared));
  try {
    check_uniforms_found({{"uX", {1.0}}}, {false}, {});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(e.info().what.find("declares no ranged uniforms"), std::string::npos);
  }
}

}  // namespace
}  // namespace ms
