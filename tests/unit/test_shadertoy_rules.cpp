// A Shadertoy JSON input of a buffer or Cube A that no pass writes loads,
// with a warning per input (Shadertoy binds it all zero); a scene's
// [[passes]] still refuses it.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "scene/project.h"
#include "importers/project_json.h"

namespace ms {
namespace {

TEST(ShadertoyRulesLoad, UnwrittenBufferAndCubeAAreWarnings) {
  const ShaderProject p = load_shadertoy_json(
      "{\"Shader\": {\"renderpass\": [{\"type\": \"image\", \"inputs\": [{\"ctype\": \"buffer\", \"id\": 259, "
      "\"channel\": 0}, {\"ctype\": \"cubemap\", \"id\": 41, \"channel\": 1}]}]}}",
      "x.json");
  ASSERT_EQ(p.passes.size(), 1u);
  EXPECT_EQ(p.passes[0].inputs[0].kind, InputKind::buffer);
  EXPECT_EQ(p.passes[0].inputs[0].buffer, 2);
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_EQ(p.warnings[0],
            "Image iChannel0 reads Buffer C, which no pass writes: it reads 0, an empty buffer of the image's size, "
            "as on Shadertoy");
  EXPECT_EQ(p.warnings[1], "Image iChannel1 reads Cube A, which no pass writes: it reads 0, an empty Cube A, as on Shadertoy");
}

TEST(ShadertoyRulesLoad, RefusedWhereAskedTo) {
  ShaderProject p = load_shadertoy_json(
      "{\"Shader\": {\"renderpass\": [{\"type\": \"image\", \"inputs\": [{\"ctype\": \"buffer\", \"id\": 258, "
      "\"channel\": 0}]}]}}",
      "x.json");
  try {
    check_project(p, "s.toml", Unwritten::refuse);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Image iChannel0 reads Buffer B, which no pass writes"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ms
