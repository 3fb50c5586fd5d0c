// shader/compute_wrap.h's text rewrite, without GL: implicit-LOD lookups
// become their Lod forms (nested calls, the offset forms), gl_FragCoord the
// invocation's coordinate, and refusals name the file:line of the call
// through the #line encoding of preprocess/preprocess.h.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "shader/compute_wrap.h"

namespace ms {
namespace {

ShaderSource source(const std::string& body) {
  ShaderSource s;
  s.text = "#version 450 core\nlayout(location = 0) out vec4 outColor;\n" + body + "void main() { outColor = f(); }\n";
  s.files = {"root.frag", "lib/inc.glsl"};
  return s;
}

TEST(ComputeWrap, ImplicitLodLookupsBecomeLodZero) {
  const ShaderSource out = wrap_compute(source(
      "uniform sampler2D a, b;\n"
      "vec4 f() { return texture(a, texture(b, gl_FragCoord.xy).xy) + textureOffset(a, vec2(0.5), ivec2(1, 0))\n"
      "  + textureProj(a, vec3(1.0)) + textureLod(a, vec2(0.0), 2.0) + texture(a, vec2(0.0), 1.0); }\n"));
  EXPECT_NE(out.text.find("textureLod(a, textureLod(b, msComputeCoord.xy, 0.0).xy, 0.0)"), std::string::npos)
      << out.text;
  EXPECT_NE(out.text.find("textureLodOffset(a, vec2(0.5), 0.0, ivec2(1, 0))"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find("textureProjLod(a, vec3(1.0), 0.0)"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find("textureLod(a, vec2(0.0), 2.0)"), std::string::npos) << out.text;  // untouched
  EXPECT_NE(out.text.find("textureLod(a, vec2(0.0), 1.0)"), std::string::npos) << out.text;  // the bias as LOD
  EXPECT_EQ(out.text.find("gl_FragCoord"), std::string::npos);
  EXPECT_NE(out.text.find("void msSceneMain()"), std::string::npos);
}

TEST(ComputeWrap, CommentsAreNotRewritten) {
  const ShaderSource out = wrap_compute(source("// texture( in a comment\nvec4 f() { return vec4(0.0); }\n"));
  EXPECT_NE(out.text.find("// texture( in a comment"), std::string::npos);
}

// The error's file:line, through an included file's encoded #line.
std::string refusal(const ShaderSource& s, bool mipmapped) {
  try {
    wrap_compute(s, {}, mipmapped);
  } catch (const Error& e) {
    return e.info().file + ":" + std::to_string(e.info().line) + ": " + e.info().what;
  }
  return "";
}

TEST(ComputeWrap, RefusalsNameTheCallsLine) {
  const std::string inc = "#line 100001 1\nfloat g() { return 1.0; }\n\nfloat h(float x) { return dFdy(x); }\n#line 4 0\n";
  const std::string d = refusal(source(inc + "vec4 f() { return vec4(h(1.0)); }\n"), false);
  EXPECT_EQ(d.rfind("lib/inc.glsl:3: ", 0), 0u) << d;
  EXPECT_NE(d.find("calls dFdy()"), std::string::npos) << d;
  const ShaderSource tex = source("uniform sampler2D a;\n\nvec4 f() { return texture(a, vec2(0.5)); }\n");
  EXPECT_EQ(refusal(tex, false), "");  // no mip chain: rewritten
  const std::string m = refusal(tex, true);
  EXPECT_EQ(m.rfind("root.frag:5: ", 0), 0u) << m;
  EXPECT_NE(m.find("mipmapped input"), std::string::npos) << m;
}

}  // namespace
}  // namespace ms
