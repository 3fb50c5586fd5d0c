// scene/writeback.h: values are changed in the TOML TEXT, so comments,
// layout and untouched numbers survive; absent keys and tables are added;
// every TOML form the loader accepts can be written; the file is replaced
// atomically and only when the new text passes the check.
#include <gtest/gtest.h>

#include <type_traits>
#include <variant>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "files.h"
#include "scene/load.h"
#include "scene/quality_fields.h"
#include "scene/writeback.h"

namespace ms {
namespace {
namespace fs = std::filesystem;

const char* kScene = R"(# my scene: keep this comment
[scene]
name = "seed"   # and this one
map  = "seed.glsl"

[camera]
position = [0.0, 1.6, -5.0]   # eye
target   = [0.0, 0.8, 0.0]
fov      = 45.0

[[lights]]
type      = "point"
position  = [4.0, 5.0, -1.5]
intensity = 2.0

[[materials]]
name  = "floor"
color = [0.8, 0.8, 0.8]

[[materials]]
name = "ball"
)";

std::string edit(const std::string& text, std::vector<TomlEdit> edits) {
  return apply_toml_edits(text, edits, "test.toml");
}

TEST(Writeback, ReplacesOnlyTheValueText) {
  const std::string out = edit(kScene, {{"camera", -1, "position", "[1.0, 2.0, 3.0]"}});
  std::string expected = kScene;
  expected.replace(expected.find("[0.0, 1.6, -5.0]"), 16, "[1.0, 2.0, 3.0]");
  EXPECT_EQ(out, expected);  // comments, alignment, other values: byte for byte
}

TEST(Writeback, AbsentKeyGoesAtTheEndOfItsTable) {
  const std::string out = edit(kScene, {{"camera", -1, "up", "[0.0, 0.0, 1.0]"}});
  EXPECT_NE(out.find("fov      = 45.0\nup = [0.0, 0.0, 1.0]\n\n[[lights]]"), std::string::npos) << out;
}

TEST(Writeback, ArrayOfTablesEntries) {
  const std::string out = edit(kScene, {{"materials", 1, "color", "[0.1, 0.2, 0.3]"},
                                        {"materials", 0, "color", "[0.5, 0.5, 0.5]"},
                                        {"lights", 0, "intensity", "3.5"}});
  EXPECT_NE(out.find("name = \"ball\"\ncolor = [0.1, 0.2, 0.3]\n"), std::string::npos) << out;
  EXPECT_NE(out.find("color = [0.5, 0.5, 0.5]\n\n[[materials]]"), std::string::npos) << out;
  EXPECT_NE(out.find("intensity = 3.5\n"), std::string::npos) << out;
  EXPECT_THROW(edit(kScene, {{"lights", 3, "intensity", "1.0"}}), Error);  // no such entry
}

TEST(Writeback, AbsentTableIsAppended) {
  const std::string out = edit(kScene, {{"quality", -1, "shadows", "false"}});
  EXPECT_NE(out.find("\n[quality]\nshadows = false\n"), std::string::npos) << out;
  EXPECT_EQ(out.rfind(kScene, 0), 0u);  // the original text is untouched before it
}

TEST(Writeback, InlineAndDottedForms) {
  const std::string text =
      "camera.fov = 30\ncamera.position = [0, 1, -4]\nsky = { horizon = [1, 1, 1] }\n"
      "lights = [ { position = [0, 5, 0] }, { type = \"directional\" } ]\n";
  const std::string out = edit(text, {{"camera", -1, "target", "[0.0, 1.0, 0.0]"},
                                      {"sky", -1, "zenith", "[0.0, 0.0, 1.0]"},
                                      {"sky", -1, "horizon", "[0.5, 0.5, 0.5]"},
                                      {"lights", 1, "intensity", "2.0"}});
  EXPECT_NE(out.find("camera.position = [0, 1, -4]\ncamera.target = [0.0, 1.0, 0.0]\n"), std::string::npos) << out;
  EXPECT_NE(out.find("sky = { horizon = [0.5, 0.5, 0.5], zenith = [0.0, 0.0, 1.0] }"), std::string::npos) << out;
  EXPECT_NE(out.find("{ type = \"directional\", intensity = 2.0 }"), std::string::npos) << out;
}

TEST(Writeback, MultiLineValuesAndUnicodeBeforeTheValue) {
  const std::string text = "[camera]\nposition = [\n  0.0,\n  1.0,\n  -5.0,\n]  # tall\n[sky]\n\"é\" = 1\n";
  const std::string out = edit(text, {{"camera", -1, "position", "[1.0, 1.0, 1.0]"}});
  EXPECT_EQ(out, "[camera]\nposition = [1.0, 1.0, 1.0]  # tall\n[sky]\n\"é\" = 1\n");
  const std::string inl = "x = { \"é\" = 1, b = 2 }\n";
  EXPECT_EQ(edit(inl, {{"x", -1, "b", "3"}}), "x = { \"é\" = 1, b = 3 }\n");
}

TEST(Writeback, InvalidInputIsAnError) {
  EXPECT_THROW(edit("[camera\n", {{"camera", -1, "fov", "1.0"}}), Error);
  EXPECT_THROW(edit("camera = 3\n", {{"camera", -1, "fov", "1.0"}}), Error);
  EXPECT_THROW(edit(kScene, {{"camera", -1, "fov", "[1.0"}}), Error);  // result would not parse
}

TEST(Writeback, ValueFormatting) {
  EXPECT_EQ(toml_float(1.6f), "1.6");
  EXPECT_EQ(toml_float(100.0f), "100.0");  // never an integer
  EXPECT_EQ(toml_float(1e-4f), "1e-04");
  EXPECT_EQ(std::stof(toml_float(0.1f + 0.2f)), 0.1f + 0.2f);  // round trip
  EXPECT_EQ(toml_vec3({0.0f, -1.5f, 2.0f}), "[0.0, -1.5, 2.0]");
  EXPECT_EQ(toml_bool(false), "false");
  EXPECT_EQ(toml_string("a\"b"), "\"a\\\"b\"");
  EXPECT_THROW(toml_float(std::nanf("")), Error);
}

TEST(Writeback, SceneValueEditsOnlyWhatChanged) {
  Scene a;
  a.lights.resize(2);
  a.lights[1].kind = LightKind::directional;
  a.materials.resize(1);
  Scene b = a;
  EXPECT_TRUE(scene_value_edits(a, b).empty());
  b.quality.shadows = false;
  b.lights[0].position = {1, 2, 3};
  b.lights[1].direction = {0, -1, 1};
  b.lights[1].position = {9, 9, 9};  // meaningless for a directional light: never written
  b.materials[0].color2 = {0, 0, 0};  // the material has no checker: never written
  b.materials[0].reflectivity = 0.5f;
  const std::vector<TomlEdit> e = scene_value_edits(a, b);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0].table, "quality");
  EXPECT_EQ(e[0].value, "false");
  EXPECT_EQ(e[1].key, "position");
  EXPECT_EQ(e[1].index, 0);
  EXPECT_EQ(e[2].key, "direction");
  EXPECT_EQ(e[2].index, 1);
  EXPECT_EQ(e[3].key, "reflectivity");
  EXPECT_EQ(camera_edits(Camera{}).size(), 4u);
}

// Every [quality] key the loader reads is one the viewer can write back
// (omega, bounds and analytic_planes too, when a preset changed them).
TEST(Writeback, SceneValueEditsCoverEveryQualityKey) {
  const Scene a;
  for (const Field<Quality>& f : kQualityFields) {
    Scene b = a;
    std::visit(
        [&](auto member) {
          using V = std::remove_reference_t<decltype(b.quality.*member)>;
          if constexpr (std::is_same_v<V, bool>) b.quality.*member = !(a.quality.*member);
          else if constexpr (std::is_same_v<V, glm::vec3>) b.quality.*member += glm::vec3(1.0f);
          else b.quality.*member = a.quality.*member + V(1);
        },
        f.member);
    const std::vector<TomlEdit> e = scene_value_edits(a, b);
    ASSERT_EQ(e.size(), 1u) << f.key;
    EXPECT_EQ(e[0].table, "quality");
    EXPECT_EQ(e[0].key, f.key);
  }
}

class WritebackFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = tmp_dir.path();
    std::ofstream(dir / "seed.glsl") << "vec2 map(vec3 p) { return vec2(length(p) - 1.0, 0.0); }\n";
    std::ofstream(dir / "scene.toml") << kScene;
  }
  std::string read() {
    std::ifstream in(dir / "scene.toml");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  test::TempDir tmp_dir;
  fs::path dir;
};

TEST_F(WritebackFile, CameraRoundTripsThroughTheLoader) {
  Camera cam;
  cam.position = {1.25f, 2.5f, -3.75f};
  cam.target = {0.1f, 0.2f, 0.3f};
  cam.up = {0.0f, 1.0f, 0.0f};
  cam.fov_deg = 37.5f;
  const fs::path file = dir / "scene.toml";
  write_toml_edits(file, camera_edits(cam), [&](const std::string& t) { parse_scene(t, file); });
  const Scene s = load_scene(file);
  EXPECT_EQ(s.camera.position, cam.position);
  EXPECT_EQ(s.camera.target, cam.target);
  EXPECT_EQ(s.camera.fov_deg, cam.fov_deg);
  EXPECT_NE(read().find("# my scene: keep this comment"), std::string::npos);
  EXPECT_NE(read().find("position = [1.25, 2.5, -3.75]   # eye"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir))  // no temporary left behind
    EXPECT_TRUE(e.path().filename() == "scene.toml" || e.path().filename() == "seed.glsl") << e.path();
}

TEST_F(WritebackFile, AFailedCheckLeavesTheFileAlone) {
  const std::string before = read();
  const fs::path file = dir / "scene.toml";
  // fov 500 is TOML but not a valid scene: the loader's check refuses it.
  EXPECT_THROW(write_toml_edits(file, {{"camera", -1, "fov", "500.0"}},
                                [&](const std::string& t) { parse_scene(t, file); }),
               Error);
  EXPECT_EQ(read(), before);
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file();
  EXPECT_EQ(n, 2);
}

TEST_F(WritebackFile, KeepsThePermissions) {
  const fs::path file = dir / "scene.toml";
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_toml_edits(file, {{"camera", -1, "fov", "50.0"}});
  EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_FLOAT_EQ(load_scene(file).camera.fov_deg, 50.0f);
}

}  // namespace
}  // namespace ms
