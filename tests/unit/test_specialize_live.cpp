// Live values (shader/specialize.h): the viewer folds what the panel is not
// dragging; a dragged value, and only it, is read from its own uniform (a
// whole entry keeps its table uniforms). folded_differences() names the
// folded values a panel edit changed.
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

// The live uniforms a text declares ("// live value: NAME" before each), in order.
std::vector<std::string> live_uniforms(const std::string& text) {
  std::vector<std::string> out;
  const std::string mark = "// live value: ";
  for (size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 1))
    out.push_back(text.substr(at + mark.size(), text.find('\n', at) - at - mark.size()));
  return out;
}

TEST(SpecializeLive, OnlyTheDraggedValueIsAUniform) {
  const Scene s = matte();
  EXPECT_EQ(tables(assembled(s, {})), "---");
  EXPECT_TRUE(live_uniforms(assembled(s, {})).empty());
  // One material field: every table stays folded, that value is a uniform.
  const std::string color = assembled(s, {"materials[1].color"});
  EXPECT_EQ(tables(color), "---");
  EXPECT_EQ(live_uniforms(color), (std::vector<std::string>{"materials[1].color"}));
  EXPECT_NE(color.find("uniform vec3 uLive_materials_1_color;"), std::string::npos);
  EXPECT_NE(color.find("Material sceneMaterial(int id) {\n  Material m;"), std::string::npos);
  EXPECT_NE(color.find("uLive_materials_1_color, "), std::string::npos) << "material 1's colour is not read from it";
  // A light by its GLSL slot, chosen by index in the folded table's macro.
  const std::string pos = assembled(s, {"lights[0].position"});
  EXPECT_EQ(tables(pos), "---");
  EXPECT_NE(pos.find("uniform vec3 uLive_lights_0_pos;"), std::string::npos);
  EXPECT_NE(pos.find("#define LIGHT_POS(i) ((i) == 0 ? uLive_lights_0_pos : kLightPos[i])"), std::string::npos);
  EXPECT_NE(pos.find("#define LIGHT_COLOR(i) kLightColor[i]"), std::string::npos) << "the colour is folded still";
  // A sky value: that uniform of the library's name, the others constants.
  const std::string sky = assembled(s, {"sky.zenith", "materials[0].specular"});
  EXPECT_EQ(tables(sky), "---");
  EXPECT_EQ(live_uniforms(sky), (std::vector<std::string>{"sky.zenith", "materials[0].specular"}));
  EXPECT_NE(sky.find("uniform vec3 uSkyZenith;"), std::string::npos);
  EXPECT_NE(sky.find("const vec3 uSkyHorizon = "), std::string::npos);
  // A whole entry keeps its table uniforms, as an animated table does.
  EXPECT_EQ(tables(assembled(s, {"lights[0]"})), "L--");
  EXPECT_EQ(tables(assembled(s, {"materials[2]"})), "-M-");
  // The same text as the viewer's former all-uniform shader in that table.
  AssembleOptions u{fs::path(MARCH_SOURCE_DIR) / "sdf_shaders", {}};
  u.specialize = Specialization::uniforms;
  EXPECT_EQ(tables(assemble_scene(s, u).text), "LMS");
}

TEST(SpecializeLive, LiveUniformNames) {
  EXPECT_EQ(live_uniform_name("materials[12].pattern_scale"), "uLive_materials_12_pattern_scale");
  EXPECT_EQ(live_uniform_name("lights[0].position"), "uLive_lights_0_pos");
  EXPECT_EQ(live_uniform_name("lights[1].direction"), "uLive_lights_1_pos");
  EXPECT_EQ(live_uniform_name("lights[1].attenuation"), "uLive_lights_1_atten");
  EXPECT_EQ(live_uniform_name("sky.ambient"), "uAmbient");
}

TEST(SpecializeLive, FoldedDifferencesNameTheEditedValues) {
  const Scene a = matte();
  Scene b = a;
  EXPECT_TRUE(folded_differences(a, b).empty());
  b.materials[1].shininess = 40.0f;
  b.materials[1].color.x = 0.5f;
  b.sky.ambient.x += 0.01f;
  b.lights[0].intensity = 3.0f;  // in the light's GLSL colour
  b.lights[0].position.y = 6.0f;
  EXPECT_EQ(folded_differences(a, b),
            (std::vector<std::string>{"lights[0].position", "lights[0].color", "materials[1].color",
                                      "materials[1].shininess", "sky.ambient"}));
  // A table of another length differs as whole entries.
  Scene d = a;
  d.materials.push_back(d.materials[0]);
  EXPECT_EQ(folded_differences(a, d), (std::vector<std::string>{"materials[3]"}));
  // What is not folded (the camera, exposure) is not a difference.
  Scene c = a;
  c.camera.fov_deg = 60.0f;
  c.render.exposure = 2.0f;
  EXPECT_TRUE(folded_differences(a, c).empty());
}

}  // namespace
}  // namespace ms
