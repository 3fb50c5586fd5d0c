// A scene file may wrap a Shadertoy shader instead of an SDF map.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/load.h"

namespace ms {
namespace {

const std::filesystem::path kData = std::filesystem::path(MARCH_TEST_DATA) / "scene";

TEST(SceneShadertoy, ResolvesTheShaderAndNeedsNoMaterials) {
  Scene s = parse_scene("[scene]\nshadertoy = \"seed.glsl\"\n[render]\nwidth = 64\n", kData / "wrap.toml");
  EXPECT_EQ(s.shadertoy_file, kData / "seed.glsl");
  EXPECT_TRUE(s.map_file.empty());
  EXPECT_TRUE(s.materials.empty());
  EXPECT_EQ(s.render.width, 64);
}

TEST(SceneShadertoy, MapAndShadertoyExcludeEachOther) {
  try {
    parse_scene("[scene]\nmap = \"seed.glsl\"\nshadertoy = \"seed.glsl\"\n", kData / "wrap.toml");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().line, 3);
    EXPECT_EQ(e.info().key, "scene.shadertoy");
  }
}

TEST(SceneShadertoy, MissingShaderFileNamesTheKey) {
  try {
    parse_scene("[scene]\nshadertoy = \"nope.glsl\"\n", kData / "wrap.toml");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().line, 2);
    EXPECT_EQ(e.info().key, "scene.shadertoy");
    EXPECT_NE(e.info().what.find("nope.glsl"), std::string::npos);
  }
}

}  // namespace
}  // namespace ms
