// Quality presets, [[planes]] and [bounds]: the scene keys and their
// file:line:key errors; --preset through the real binary. The step-count
// bounds of every preset on every scene are cases of tests/cost/suite.toml
// (ctest: cost_suite). The tracer itself: test_tracer.cpp.
#include <gtest/gtest.h>

#include "core/error.h"
#include "run.h"
#include "scene/load.h"
#include "scene/quality.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

std::string scene(const std::string& name) { return (source_dir() / "scenes" / (name + ".toml")).string(); }
// Parsed as if it sat next to the shipped scenes (so map = "seed.glsl" resolves).
fs::path inline_path() { return source_dir() / "scenes" / "inline.toml"; }

// Lines 1-4; a case's body starts on line 5.
constexpr const char* kBase =
    "[scene]\n"
    "map = \"seed.glsl\"\n"
    "[[materials]]\n"
    "name = \"floor\"\n";

ErrorInfo error_of(const std::string& body) {
  try {
    parse_scene(kBase + body, inline_path());
  } catch (const Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for:\n" << body;
  return {};
}

struct Case {
  const char* name;
  std::string body;
  int line;
  std::string key;
  std::string what;  // substring of what
  std::string hint;  // substring of hint; "" = any
};

class SceneKeyError : public ::testing::TestWithParam<Case> {};

TEST_P(SceneKeyError, NamesFileLineAndKey) {
  const Case& c = GetParam();
  const ErrorInfo e = error_of(c.body);
  EXPECT_EQ(e.code, Exit::bad_input);
  EXPECT_EQ(e.file, inline_path().string());
  EXPECT_EQ(e.line, c.line) << format_error(e);
  EXPECT_EQ(e.key, c.key) << format_error(e);
  EXPECT_NE(e.what.find(c.what), std::string::npos) << e.what;
  EXPECT_NE(e.hint.find(c.hint), std::string::npos) << e.hint;
  EXPECT_EQ(format_error(e).find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    All, SceneKeyError,
    ::testing::Values(
        Case{"PresetTypo", "[quality]\npreset = \"balnced\"\n", 6, "quality.preset", "unknown value 'balnced'",
             "did you mean 'balanced'?"},
        Case{"PresetNotString", "[quality]\npreset = 3\n", 6, "quality.preset", "must be a string", ""},
        Case{"OmegaTwo", "[quality]\nomega = 2.0\n", 6, "quality.omega", "must be in [1, 2)", ""},
        Case{"OmegaBelowOne", "[quality]\nomega = 0.9\n", 6, "quality.omega", "must be in [1, 2)", ""},
        Case{"BoundsFlagNotBool", "[quality]\nbounds = 1\n", 6, "quality.bounds", "must be true or false", ""},
        Case{"PlaneKeyTypo", "[[planes]]\nnromal = [0, 1, 0]\n", 6, "planes[0].nromal", "unknown key",
             "did you mean 'normal'?"},
        Case{"PlaneNormalZero", "[[planes]]\nmaterial = \"floor\"\nnormal = [0, 0, 0]\n", 7, "planes[0].normal",
             "must not be zero-length", ""},
        Case{"PlaneNormalTwoNumbers", "[[planes]]\nnormal = [0, 1]\n", 6, "planes[0].normal",
             "must be an array of 3 numbers", ""},
        Case{"PlaneOffsetNan", "[[planes]]\noffset = nan\n", 6, "planes[0].offset", "finite", ""},
        Case{"PlaneMaterialMissing", "[[planes]]\nnormal = [0, 1, 0]\n", 5, "planes[0].material",
             "missing required key 'planes[0].material'", "material = \"floor\""},
        Case{"PlaneMaterialUnknown", "[[planes]]\nmaterial = \"flor\"\n", 6, "planes[0].material",
             "unknown material 'flor'", "did you mean 'floor'?"},
        Case{"SecondPlane", "[[planes]]\nmaterial = \"floor\"\n[[planes]]\nmaterial = \"wall\"\n", 8,
             "planes[1].material", "unknown material 'wall'", "[[materials]]"},
        Case{"PlanesNotArray", "[planes]\nmaterial = \"floor\"\n", 5, "planes", "must be an array of tables",
             "[[planes]]"},
        Case{"BoundsKeyTypo", "[bounds]\ncentre = [0, 0, 0]\n", 6, "bounds.centre", "unknown key",
             "did you mean 'center'?"},
        Case{"BoundsBoth", "[bounds]\ncenter = [0, 0, 0]\nradius = 1\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n", 8,
             "bounds", "either a sphere", ""},
        Case{"BoundsNoRadius", "[bounds]\ncenter = [0, 0, 0]\n", 6, "bounds.radius",
             "'bounds.center' needs 'bounds.radius'", "center and radius"},
        Case{"BoundsNoCenter", "[bounds]\nradius = 2\n", 6, "bounds.center", "'bounds.radius' needs 'bounds.center'",
             ""},
        Case{"BoundsRadiusZero", "[bounds]\ncenter = [0, 0, 0]\nradius = 0\n", 7, "bounds.radius", "must be > 0", ""},
        Case{"BoundsNoMax", "[bounds]\nmin = [0, 0, 0]\n", 6, "bounds.max", "'bounds.min' needs 'bounds.max'", ""},
        Case{"BoundsInverted", "[bounds]\nmin = [0, 0, 0]\nmax = [1, 0, 1]\n", 7, "bounds.max",
             "must be greater than 'bounds.min'", ""},
        Case{"BoundsEmpty", "[bounds]\n", 5, "bounds", "[bounds] is empty", "center and radius"}),
    [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

TEST(ScenePlanes, TooManyPlanes) {
  std::string body;
  for (int i = 0; i < 9; ++i) body += "[[planes]]\nmaterial = \"floor\"\n";
  const ErrorInfo e = error_of(body);
  EXPECT_EQ(e.key, "planes");
  EXPECT_EQ(e.line, 5 + 2 * 8);
  EXPECT_NE(e.what.find("at most 8"), std::string::npos) << e.what;
}

TEST(ScenePlanes, NormalIsNormalisedAndMaterialResolved) {
  const Scene s = parse_scene(std::string(kBase) +
                                  "[[materials]]\nname = \"ball\"\n[[planes]]\nnormal = [0, 2, 0]\noffset = -0.5\n"
                                  "material = \"ball\"\n[bounds]\nmin = [-1, 0, -1]\nmax = [1, 2, 1]\n",
                              inline_path());
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].normal, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(s.planes[0].offset, -0.5f);
  EXPECT_EQ(s.planes[0].material_id, 1);
  EXPECT_EQ(s.bounds.kind, BoundsKind::box);
  EXPECT_EQ(s.bounds.max, glm::vec3(1.0f, 2.0f, 1.0f));
}

TEST(QualityPresets, ExplicitKeysOverrideThePreset) {
  const Scene s = parse_scene(std::string(kBase) + "[quality]\npreset = \"fast\"\nmax_steps = 300\n", inline_path());
  const Quality fast = preset_quality("fast");
  EXPECT_EQ(s.quality.preset, "fast");
  EXPECT_EQ(s.quality.max_steps, 300);                          // explicit
  EXPECT_EQ(s.quality.hit_tolerance, fast.hit_tolerance);       // from the preset
  EXPECT_EQ(s.quality.explicit_keys, std::vector<std::string>{"max_steps"});
  // --preset re-bases the scene and keeps the explicit key.
  const Quality ref = with_preset(s.quality, "reference");
  EXPECT_EQ(ref.max_steps, 300);
  EXPECT_EQ(ref.hit_tolerance, preset_quality("reference").hit_tolerance);
  EXPECT_EQ(ref.preset, "reference");
  // No [quality]: balanced, the struct's defaults.
  const Scene plain = parse_scene(kBase, inline_path());
  EXPECT_EQ(plain.quality.preset, "balanced");
  EXPECT_EQ(plain.quality.omega, preset_quality("balanced").omega);
  EXPECT_EQ(plain.quality.max_steps, Quality{}.max_steps);
  EXPECT_THROW(preset_quality("quick"), Error);
}

TEST(QualityPresets, TheyOrderCostAndAccuracy) {
  const Quality f = preset_quality("fast"), b = preset_quality("balanced"), r = preset_quality("reference"),
                t = preset_quality("textbook");
  EXPECT_GT(f.hit_tolerance, b.hit_tolerance);
  EXPECT_GT(b.hit_tolerance, r.hit_tolerance);
  EXPECT_LE(f.max_steps, b.max_steps);
  EXPECT_LT(b.max_steps, r.max_steps);
  EXPECT_EQ(r.omega, 1.0f);  // the reference does not relax
  EXPECT_TRUE(f.bounds && b.bounds && r.bounds && f.analytic_planes && b.analytic_planes && r.analytic_planes);
  // The baseline, exactly as the issue defines it.
  EXPECT_EQ(t.max_steps, 255);
  EXPECT_EQ(t.hit_tolerance, 0.0f);
  EXPECT_EQ(t.hit_epsilon, 1e-4f);
  EXPECT_EQ(t.max_distance, 100.0f);
  EXPECT_EQ(t.omega, 1.0f);
  EXPECT_FALSE(t.bounds || t.analytic_planes);
}

TEST(PresetFlag, RenderAndBenchAcceptItAndRejectNonsense) {
  TempDir dir;
  const RunResult ok = run_marchstudio(
      {"render", scene("seed"), "--preset", "textbook", "--size", "16x9", "-o", (dir / "t.png").string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const RunResult bad = run_marchstudio(
      {"render", scene("seed"), "--preset", "ultra", "--size", "16x9", "-o", (dir / "u.png").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--preset"), std::string::npos) << bad.err;
  const RunResult toy = run_marchstudio({"render", (source_dir() / "tests/data/shader/shadertoy/ok.glsl").string(),
                                         "--preset", "fast", "--size", "16x9", "-o", (dir / "s.png").string()});
  EXPECT_EQ(toy.exit_code, 2) << toy.err;
  EXPECT_NE(toy.err.find("--preset"), std::string::npos) << toy.err;
  const RunResult b = run_marchstudio(
      {"bench", scene("seed"), "--preset", "fast", "--size", "16x9", "--frames", "1", "--warmup", "0", "--json"});
  EXPECT_EQ(b.exit_code, 0) << b.err;
}

}  // namespace
}  // namespace ms::test
