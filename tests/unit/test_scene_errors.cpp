// Scene validation: each mistake is one ms::Error (bad_input) naming the
// file as given, the line, the dotted key, and a hint where one helps.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/load.h"

namespace fs = std::filesystem;

namespace {

const fs::path kDir = fs::path(MARCH_TEST_DATA) / "scene";
const fs::path kInline = kDir / "inline.toml";

// Lines 1-4; a case's body starts on line 5.
constexpr const char* kBase =
    "[scene]\n"
    "map = \"seed.glsl\"\n"
    "[[materials]]\n"
    "name = \"floor\"\n";

ms::ErrorInfo error_of(const std::string& text, const fs::path& path = kInline) {
  try {
    ms::parse_scene(text, path);
  } catch (const ms::Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

void expect_one_line(const ms::ErrorInfo& e) {
  EXPECT_EQ(ms::format_error(e).find('\n'), std::string::npos) << ms::format_error(e);
}

struct Case {
  const char* name;
  std::string body;   // appended after kBase (unless `whole`)
  int line;
  std::string key;
  std::string what;   // a substring of ErrorInfo::what
  std::string hint;   // a substring of ErrorInfo::hint; "" means the hint must be empty
  bool whole = false; // body is the whole file
};

class SceneError : public ::testing::TestWithParam<Case> {};

TEST_P(SceneError, NamesFileLineKeyAndHint) {
  const Case& c = GetParam();
  const ms::ErrorInfo e = error_of(c.whole ? c.body : kBase + c.body);
  EXPECT_EQ(e.code, ms::Exit::bad_input);
  EXPECT_EQ(e.file, kInline.string());
  EXPECT_EQ(e.line, c.line) << ms::format_error(e);
  EXPECT_EQ(e.key, c.key) << ms::format_error(e);
  EXPECT_NE(e.what.find(c.what), std::string::npos) << "what: " << e.what;
  if (c.hint.empty()) EXPECT_EQ(e.hint, "");
  else EXPECT_NE(e.hint.find(c.hint), std::string::npos) << "hint: " << e.hint;
  expect_one_line(e);
}

const Case kCases[] = {
    // Malformed TOML: line from toml++, no key.
    {"UnclosedTable", "\n[camera\nfov = 1\n", 6, "", "invalid TOML", ""},
    {"DuplicateKey", "[camera]\nfov = 1\nfov = 2\n", 7, "", "invalid TOML", ""},
    // Unknown keys with did-you-mean, in tables, at top level, in arrays.
    {"CameraTypo", "[camera]\nfvo = 30\n", 6, "camera.fvo", "unknown key 'camera.fvo'", "did you mean 'fov'?"},
    {"TopLevelTypo", "\n\n[[lihgt]]\n", 7, "lihgt", "unknown key 'lihgt'", "did you mean 'lights'?"},
    {"LightKeyTypo", "[[lights]]\ncolr = [1, 1, 1]\n", 6, "lights[0].colr", "unknown key 'lights[0].colr'",
     "did you mean 'color'?"},
    {"SecondMaterialTypo", "[[materials]]\nname = \"b\"\nshinyness = 3\n", 7, "materials[1].shinyness",
     "unknown key", "did you mean 'shininess'?"},
    {"MisplacedKey", "[camera]\nwidth = 5\n", 6, "camera.width", "unknown key", "'width' belongs in [render]"},
    {"MisplacedTopLevel", std::string("fov = 5\n") + kBase, 1, "fov", "unknown key 'fov'",
     "'fov' belongs in [camera]", true},
    {"UnknownNoHint", "[quality]\nbanana = 1\n", 6, "quality.banana", "unknown key", ""},
    {"ControlCharKeyStaysOneLine", std::string("\"a\\nb\" = 1\n") + kBase, 1, "a\\nb", "unknown key 'a\\nb'",
     "", true},
    // Wrong types, naming the expected type.
    {"WidthString", "[render]\nwidth = \"big\"\n", 6, "render.width", "must be an integer, not a string", ""},
    {"WidthExponent", "[render]\nwidth = 1e3\n", 6, "render.width", "must be an integer, not a float",
     "write it as 1000"},
    {"WidthFraction", "[render]\nwidth = 1.5\n", 6, "render.width", "must be an integer, not a float", ""},
    {"TopLevelCase", "\n[Camera]\n", 6, "Camera", "unknown key 'Camera'", "did you mean 'camera'?"},
    {"WidthFloat", "[render]\nwidth = 12.0\n", 6, "render.width", "must be an integer, not a float",
     "write it as 12"},
    {"FovString", "[camera]\nfov = \"wide\"\n", 6, "camera.fov", "must be a number, not a string", ""},
    {"PositionTwoNumbers", "[camera]\nposition = [1, 2]\n", 6, "camera.position",
     "must be an array of 3 numbers, got 2 elements", ""},
    {"PositionScalar", "[camera]\nposition = 1\n", 6, "camera.position",
     "must be an array of 3 numbers, not an integer", ""},
    {"PositionElementString", "[camera]\nposition = [0, \"1\", 2]\n", 6, "camera.position",
     "'camera.position[1]' must be a number, not a string", ""},
    {"BoolAsInt", "[quality]\nshadows = 1\n", 6, "quality.shadows", "must be true or false, not an integer", ""},
    {"NameNotString", "[[materials]]\nname = 5\n", 6, "materials[1].name", "must be a string, not an integer", ""},
    {"TableNotTable", std::string("camera = 5\n") + kBase, 1, "camera", "'camera' must be a table, not an integer",
     "", true},
    {"LightsNotArray", std::string("lights = 5\n") + kBase, 1, "lights", "must be an array of tables",
     "write [[lights]] above each entry", true},
    {"LightsSingleBrackets", "[lights]\ntype = \"point\"\n", 5, "lights", "'lights' must be an array of tables, not a table",
     "write [[lights]] above each entry"},
    {"CameraDoubleBrackets", "[[camera]]\n", 5, "camera", "'camera' must be a table, not an array",
     "write [camera], not [[camera]]"},
    {"LightsElementNotTable", std::string("lights = [1]\n") + kBase, 1, "lights[0]",
     "'lights[0]' must be a table, not an integer", "", true},
    {"TimeIsADate", "[render]\ntime = 1979-05-27\n", 6, "render.time", "must be a number, not a date", ""},
    // NaN and Inf anywhere a number is accepted.
    {"NanFov", "[camera]\nfov = nan\n", 6, "camera.fov", "must be a finite number, got nan", ""},
    {"InfExposure", "[render]\nexposure = +inf\n", 6, "render.exposure", "must be a finite number, got inf", ""},
    {"NanTime", "[render]\ntime = -nan\n", 6, "render.time", "must be a finite number", ""},
    {"InfInVector", "[camera]\ntarget = [0, -inf, 0]\n", 6, "camera.target",
     "'camera.target[1]' must be a finite number, got -inf", ""},
    {"NanLightIntensity", "[[lights]]\nintensity = nan\n", 6, "lights[0].intensity", "finite", ""},
    {"NanVelocity", "[[materials]]\nname = \"b\"\npattern_velocity = [nan, 0, 0]\n", 7,
     "materials[1].pattern_velocity", "finite", ""},
    // Float overflow and underflow for 32-bit floats.
    {"TooLargeForFloat", "[quality]\nmax_distance = 1e39\n", 6, "quality.max_distance",
     "too large for a 32-bit float", ""},
    {"UnderflowsToZero", "[quality]\nhit_epsilon = 1e-50\n", 6, "quality.hit_epsilon", "must be > 0",
     "rounds to 0 as a 32-bit float"},
    // Ranges.
    {"WidthZero", "[render]\nwidth = 0\n", 6, "render.width", "must be in [1, 16384], got 0", ""},
    {"HeightTooBig", "[render]\nheight = 16385\n", 6, "render.height", "must be in [1, 16384], got 16385", ""},
    {"HugeInteger", "[render]\nwidth = 9223372036854775807\n", 6, "render.width", "must be in [1, 16384]", ""},
    {"SppZero", "[render]\nspp = 0\n", 6, "render.spp", "must be in [1, 1024]", ""},
    {"SppTooMany", "[render]\nspp = 1025\n", 6, "render.spp", "must be in [1, 1024]", ""},
    {"FovZero", "[camera]\nfov = 0\n", 6, "camera.fov", "must be in (0, 180), got 0", ""},
    {"Fov180", "[camera]\nfov = 180.0\n", 6, "camera.fov", "must be in (0, 180), got 180", ""},
    {"ExposureZero", "[render]\nexposure = 0\n", 6, "render.exposure", "must be > 0", ""},
    {"MaxStepsZero", "[quality]\nmax_steps = 0\n", 6, "quality.max_steps", "must be in [1, 100000]", ""},
    {"MaxDistanceNeg", "[quality]\nmax_distance = -1\n", 6, "quality.max_distance", "must be > 0", ""},
    {"HitToleranceNeg", "[quality]\nhit_tolerance = -0.5\n", 6, "quality.hit_tolerance", "must be >= 0", ""},
    {"LipschitzBelowOne", "[quality]\nlipschitz = 0.5\n", 6, "quality.lipschitz", "must be >= 1, got 0.5", ""},
    {"ShadowStepsNeg", "[quality]\nshadow_steps = -1\n", 6, "quality.shadow_steps", "must be in [0, 10000]", ""},
    {"AoTapsTooMany", "[quality]\nao_taps = 65\n", 6, "quality.ao_taps", "must be in [0, 64]", ""},
    {"BouncesTooMany", "[quality]\nbounces = 17\n", 6, "quality.bounces", "must be in [0, 16]", ""},
    {"SkyNegative", "[sky]\nzenith = [0, -0.1, 0]\n", 6, "sky.zenith", "'sky.zenith[1]' must be >= 0", ""},
    {"LightColorNeg", "[[lights]]\ncolor = [-1, 0, 0]\n", 6, "lights[0].color", "'lights[0].color[0]' must be >= 0", ""},
    {"LightIntensityNeg", "[[lights]]\nintensity = -1\n", 6, "lights[0].intensity", "must be >= 0", ""},
    {"LightSizeNeg", "[[lights]]\nsize = -0.1\n", 6, "lights[0].size", "must be >= 0", ""},
    {"AttenuationNeg", "[[lights]]\nattenuation = [1, -1, 0]\n", 6, "lights[0].attenuation", "must be >= 0", ""},
    {"ReflectivityAboveOne", "[[materials]]\nname = \"m\"\nreflectivity = 1.5\n", 7, "materials[1].reflectivity",
     "must be in [0, 1]", ""},
    {"ShininessZero", "[[materials]]\nname = \"m\"\nshininess = 0\n", 7, "materials[1].shininess", "must be > 0", ""},
    {"PatternScaleZero", "[[materials]]\nname = \"m\"\npattern_scale = 0\n", 7, "materials[1].pattern_scale",
     "must be > 0", ""},
    {"DiffuseNeg", "[[materials]]\nname = \"m\"\ndiffuse = -1\n", 7, "materials[1].diffuse", "must be >= 0", ""},
    // Degenerate geometry.
    {"ZeroDirection", "[[lights]]\ntype = \"directional\"\ndirection = [0, 0, 0]\n", 7, "lights[0].direction",
     "must not be zero-length", ""},
    {"ZeroUp", "[camera]\nup = [0, 0, 0]\n", 6, "camera.up", "'camera.up' must not be zero-length", ""},
    {"PositionIsTarget", "[camera]\nposition = [1, 2, 3]\ntarget = [1, 2, 3]\n", 7, "camera.target",
     "must differ from 'camera.position'", "looks from position towards target"},
    {"UpParallelToView", "[camera]\nposition = [0, 5, 0]\ntarget = [0, 0, 0]\n", 5, "camera.up",
     "'camera.up' is parallel to the view direction", "defaults to [0, 1, 0]"},
    {"AttenuationAllZero", "[[lights]]\nattenuation = [0, 0, 0]\n", 6, "lights[0].attenuation",
     "must not be all zero", "[1, 0, 0]"},
    {"DirectionalSize180", "[[lights]]\ntype = \"directional\"\nsize = 180\n", 7, "lights[0].size",
     "must be in [0, 180) for a directional light", "angular diameter"},
    // Unknown enum values.
    {"TonemapTypo", "[render]\ntonemap = \"acse\"\n", 6, "render.tonemap",
     "unknown value 'acse' for 'render.tonemap'", "did you mean 'aces'?"},
    {"TonemapNoClose", "[render]\ntonemap = \"filmic\"\n", 6, "render.tonemap", "unknown value 'filmic'",
     "expected 'none', 'reinhard' or 'aces'"},
    {"TonemapCase", "[render]\ntonemap = \"ACES\"\n", 6, "render.tonemap", "unknown value 'ACES'",
     "did you mean 'aces'?"},
    {"LightTypeTypo", "[[lights]]\ntype = \"pont\"\n", 6, "lights[0].type", "unknown value 'pont'",
     "did you mean 'point'?"},
    {"PatternTypo", "[[materials]]\nname = \"m\"\npattern = \"checkers\"\n", 7, "materials[1].pattern",
     "unknown value 'checkers'", "did you mean 'checker'?"},
    // Keys a light's type ignores.
    {"PositionOnDirectional", "[[lights]]\ntype = \"directional\"\nposition = [0, 1, 0]\n", 7, "lights[0].position",
     "'lights[0].position' does nothing for a directional light", "set type = \"point\""},
    {"AttenuationOnDirectional", "[[lights]]\nattenuation = [1, 0, 0]\ntype = \"directional\"\n", 6,
     "lights[0].attenuation", "does nothing for a directional light", "set type = \"point\""},
    {"DirectionOnPoint", "[[lights]]\ndirection = [0, -1, 0]\n", 6, "lights[0].direction",
     "does nothing for a point light", "set type = \"directional\""},
    // Materials.
    {"DuplicateMaterial", "[[materials]]\nname = \"Floor\"\n", 6, "materials[1].name",
     "duplicate material name 'Floor'", "materials[0] is already 'floor'"},
    {"MaterialNotIdentifier", "[[materials]]\nname = \"my-mat\"\n", 6, "materials[1].name", "is not an identifier",
     "letters, digits"},
    {"MaterialLeadingDigit", "[[materials]]\nname = \"1st\"\n", 6, "materials[1].name", "is not an identifier",
     "not starting with a digit"},
    {"MaterialEmptyName", "[[materials]]\nname = \"\"\n", 6, "materials[1].name", "is not an identifier",
     "letters"},
    {"MaterialDoubleUnderscore", "[[materials]]\nname = \"a__b\"\n", 6, "materials[1].name", "'__'", "'__'"},
    {"MaterialLeadingUnderscore", "[[materials]]\nname = \"_b\"\n", 6, "materials[1].name", "'__'", "'_'"},
    {"MaterialWithoutName", "\n[[materials]]\ncolor = [1, 1, 1]\n", 6, "materials[1].name",
     "missing required key 'materials[1].name'", "needs a name"},
    {"NoMaterials", "[scene]\nmap = \"seed.glsl\"\n", 0, "materials", "the scene defines no materials",
     "[[materials]]", true},
    {"EmptyMaterials", "materials = []\n[scene]\nmap = \"seed.glsl\"\n", 1, "materials",
     "the scene defines no materials", "[[materials]]", true},
    // scene.map.
    {"NoSceneTable", "[[materials]]\nname = \"m\"\n", 0, "scene.map", "one of 'scene.map', 'scene.graph' or 'scene.shadertoy' is required",
     "vec2 map(vec3 p)", true},
    {"SceneWithoutMap", "[[materials]]\nname = \"m\"\n\n[scene]\nname = \"x\"\n", 4, "scene.map",
     "one of 'scene.map', 'scene.graph' or 'scene.shadertoy' is required", "vec2 map", true},
    {"EmptyMap", "[scene]\n\nmap = \"\"\n[[materials]]\nname = \"m\"\n", 3, "scene.map", "must not be empty", "",
     true},
    {"MapIsDirectory", "[scene]\nmap = \"nested\"\n[[materials]]\nname = \"m\"\n", 2, "scene.map", "is a directory",
     "", true},
};

INSTANTIATE_TEST_SUITE_P(All, SceneError, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(SceneErrors, MissingMapNamesTheMapLineAndResolvedPath) {
  const fs::path display = kDir / "nested" / "x.toml";
  const ms::ErrorInfo e = error_of("[[materials]]\nname = \"m\"\n[scene]\nmap = \"missing.glsl\"\n", display);
  EXPECT_EQ(e.code, ms::Exit::bad_input);
  EXPECT_EQ(e.file, display.string());
  EXPECT_EQ(e.line, 4);
  EXPECT_EQ(e.key, "scene.map");
  EXPECT_NE(e.what.find("map file '" + (kDir / "nested" / "missing.glsl").string() + "' not found"),
            std::string::npos)
      << e.what;
  EXPECT_NE(e.hint.find("relative to the scene file"), std::string::npos) << e.hint;
}

TEST(SceneErrors, SceneErrorsComeBeforeAMissingMap) {
  const ms::ErrorInfo e = error_of("[scene]\nmap = \"missing.glsl\"\n[camera]\nfvo = 1\n");
  EXPECT_EQ(e.key, "camera.fvo");
  EXPECT_EQ(e.line, 4);
}

TEST(SceneErrors, TooManyLightsPointsAtTheNinth) {
  std::string text = kBase;
  for (int i = 0; i < 9; ++i) text += "[[lights]]\n";  // lights on lines 5..13
  const ms::ErrorInfo e = error_of(text);
  EXPECT_EQ(e.key, "lights");
  EXPECT_EQ(e.line, 13);
  EXPECT_NE(e.what.find("too many lights: 9 (at most 8)"), std::string::npos) << e.what;
  // Eight are fine.
  std::string eight = kBase;
  for (int i = 0; i < 8; ++i) eight += "[[lights]]\n";
  EXPECT_EQ(ms::parse_scene(eight, kInline).lights.size(), 8u);
}

TEST(SceneErrors, TooManyMaterialsPointsAtTheThirtyThird) {
  std::string text = "[scene]\nmap = \"seed.glsl\"\n";
  for (int i = 0; i < 33; ++i) text += "[[materials]]\nname = \"m" + std::to_string(i) + "\"\n";
  const ms::ErrorInfo e = error_of(text);
  EXPECT_EQ(e.key, "materials");
  EXPECT_EQ(e.line, 3 + 2 * 32);  // the 33rd [[materials]] header
  EXPECT_NE(e.what.find("too many materials: 33 (at most 32)"), std::string::npos) << e.what;
}

TEST(SceneErrors, MissingSceneFileNamesThePathAsGiven) {
  try {
    ms::load_scene("no/such/scene.toml");
    FAIL() << "no error";
  } catch (const ms::Error& e) {
    EXPECT_EQ(e.code(), ms::Exit::bad_input);
    EXPECT_EQ(e.info().file, "no/such/scene.toml");
    EXPECT_EQ(e.info().line, 0);
    EXPECT_EQ(ms::format_error(e.info()), "no/such/scene.toml: scene file not found");
  }
}

TEST(SceneErrors, SceneFileThatIsADirectory) {
  try {
    ms::load_scene(kDir);
    FAIL() << "no error";
  } catch (const ms::Error& e) {
    EXPECT_EQ(e.code(), ms::Exit::bad_input);
    EXPECT_EQ(e.info().what, "scene file is a directory, not a regular file");
  }
}

TEST(SceneErrors, ErrorFromAFileUsesTheRelativePathAsGiven) {
  const fs::path rel = fs::relative(kDir / "bad_key.toml");
  try {
    ms::load_scene(rel);
    FAIL() << "no error";
  } catch (const ms::Error& e) {
    EXPECT_EQ(std::string(e.what()), rel.string() + ":6: unknown key 'camera.fvo' (did you mean 'fov'?)");
    EXPECT_EQ(e.info().key, "camera.fvo");
  }
}

TEST(SceneErrors, LongGarbageKeyIsCutAndStaysOneLine) {
  const std::string key(5000, 'x');
  const ms::ErrorInfo e = error_of(std::string(kBase) + key + " = 1\n");
  EXPECT_EQ(e.line, 5);
  EXPECT_LT(ms::format_error(e).size(), 300u);
  EXPECT_NE(e.what.find("..."), std::string::npos);
  expect_one_line(e);
}

}  // namespace
