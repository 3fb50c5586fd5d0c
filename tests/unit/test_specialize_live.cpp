// Live values (shader/specialize.h): the viewer folds what the panel is not
// dragging; a dragged value's table, and only its table, stays uniforms.
// folded_differences() names the folded entries a panel edit changed.
#include <gtest/gtest.h>


#include "scene/load.h"
#include "shader/assemble.h"
#include "shader/specialize.h"

namespace ms {
namespace {

namespace fs = std::filesystem;

Scene matte() { return load_scene(fs::path(MARCH_TEST_DATA) / "specialize" / "matte.toml"); }

std::string assembled(const Scene& s, std::vector<std::string> live) {
  AssembleOptions o{fs::path(MARCH_SOURCE_DIR) / "sdf_shaders", {}};
  o.specialize = Specialization::folded;
  o.live = std::move(live);
  return assemble_scene(s, o).text;
}

// Which tables the text reads from uniforms, e.g. "L-S": lights and sky.
std::string tables(const std::string& text) {
  std::string out;
  for (const char* t : {"LIGHT", "MATERIAL", "SKY"}) {
    const bool on = text.find(std::string("#define ") + t + "_UNIFORMS 1\n") != std::string::npos;
    EXPECT_NE(on, text.find(std::string("#define ") + t + "_UNIFORMS 0\n") != std::string::npos) << t;
    out += on ? std::string(1, t[0]) : "-";
  }
  return out;
}

TEST(SpecializeLive, OnlyTheDraggedValuesTableStaysUniforms) {
  const Scene s = matte();
  EXPECT_EQ(tables(assembled(s, {})), "---");
  EXPECT_EQ(tables(assembled(s, {"materials[1].color"})), "-M-");
  EXPECT_EQ(tables(assembled(s, {"lights[0]"})), "L--");
  EXPECT_EQ(tables(assembled(s, {"sky.zenith"})), "--S");
  EXPECT_EQ(tables(assembled(s, {"lights[0]", "sky.horizon"})), "L-S");
  // A live material keeps the library's uniform lookup, not the folded table.
  const std::string live = assembled(s, {"materials[2]"});
  EXPECT_EQ(live.find("Material sceneMaterial(int id) {\n  Material m;"), std::string::npos);
  EXPECT_NE(live.find("kLightPos"), std::string::npos) << "the lights are no longer folded";
  // The same text as the viewer's former all-uniform shader in that table.
  AssembleOptions u{fs::path(MARCH_SOURCE_DIR) / "sdf_shaders", {}};
  u.specialize = Specialization::uniforms;
  EXPECT_EQ(tables(assemble_scene(s, u).text), "LMS");
}

TEST(SpecializeLive, FoldedDifferencesNameTheEditedEntries) {
  const Scene a = matte();
  Scene b = a;
  EXPECT_TRUE(folded_differences(a, b).empty());
  b.materials[1].shininess = 40.0f;
  b.sky.ambient.x += 0.01f;
  b.lights[0].intensity = 3.0f;
  EXPECT_EQ(folded_differences(a, b), (std::vector<std::string>{"lights[0]", "materials[1]", "sky.ambient"}));
  // What is not folded (the camera, exposure) is not a difference.
  Scene c = a;
  c.camera.fov_deg = 60.0f;
  c.render.exposure = 2.0f;
  EXPECT_TRUE(folded_differences(a, c).empty());
}

}  // namespace
}  // namespace ms
