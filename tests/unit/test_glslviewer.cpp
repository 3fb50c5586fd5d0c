// glslViewer files (importers/glslviewer.h): what is recognised, the passes a
// file becomes, and refusals at their line. No GL.
#include <gtest/gtest.h>

#include "core/error.h"
#include "importers/glslviewer.h"

namespace ms {
namespace {

TEST(GlslViewer, RecognisedByMainWithGlFragColorOrUniforms) {
  EXPECT_TRUE(looks_like_glslviewer("uniform float u_time;\nvoid main() { gl_FragColor = vec4(u_time); }"));
  EXPECT_TRUE(looks_like_glslviewer("void main(void) { gl_FragColor = vec4(1.0); }"));
  EXPECT_FALSE(looks_like_glslviewer("void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }"));
  EXPECT_FALSE(looks_like_glslviewer("// gl_FragColor\nvoid main() { }"));
  EXPECT_FALSE(looks_like_glslviewer("vec2 map(vec3 p) { return vec2(0.0); }"));
}

TEST(GlslViewer, BuffersThenDoubleBuffersThenMain) {
  const std::string src =
      "uniform sampler2D u_buffer0;\nuniform sampler2D u_doubleBuffer0;\nuniform sampler2D u_tex0;\n"
      "void main() {\n#ifdef BUFFER_0\n gl_FragColor = vec4(1.0);\n#elif defined(DOUBLE_BUFFER_0)\n"
      " gl_FragColor = texture2D(u_doubleBuffer0, vec2(0.0));\n#else\n gl_FragColor = texture2D(u_buffer0, vec2(0.0));\n#endif\n}\n";
  const ShaderProject p = load_glslviewer(src, "/tmp/x.frag");
  ASSERT_EQ(p.passes.size(), 3u);
  EXPECT_EQ(p.passes[0].define, "BUFFER_0");
  EXPECT_EQ(p.passes[0].output, 0);
  EXPECT_EQ(p.passes[0].inputs[0].kind, InputKind::none);  // never bound to itself, as glslViewer
  EXPECT_EQ(p.passes[1].define, "DOUBLE_BUFFER_0");
  EXPECT_EQ(p.passes[1].output, 1);
  EXPECT_EQ(p.passes[1].inputs[1].buffer, 1);  // reads its own previous frame
  EXPECT_EQ(p.passes[2].kind, PassKind::image);
  EXPECT_EQ(p.passes[2].inputs[0].buffer, 0);
  EXPECT_EQ(p.passes[2].inputs[2].uniform, "u_tex0");
}

std::string error_of(const std::string& src) {
  try {
    load_glslviewer(src, "/tmp/x.frag");
  } catch (const Error& e) {
    return std::to_string(e.info().line) + ": " + e.info().what;
  }
  return "no error";
}

// POSTPROCESSING: main draws into a buffer after the others, and the same
// file with POSTPROCESSING defined draws the image, reading it as u_scene.
TEST(GlslViewer, PostprocessingReadsMainsImageAsUScene) {
  const ShaderProject p = load_glslviewer(
      "uniform sampler2D u_scene;\nuniform sampler2D u_doubleBuffer0;\nvoid main() {\n#ifdef DOUBLE_BUFFER_0\n#endif\n"
      "#ifdef POSTPROCESSING\n#endif\n}\n",
      "/tmp/x.frag");
  ASSERT_EQ(p.passes.size(), 3u);
  EXPECT_EQ(p.passes[0].define, "DOUBLE_BUFFER_0");
  EXPECT_EQ(p.passes[1].define, "");
  EXPECT_EQ(p.passes[1].kind, PassKind::buffer);
  EXPECT_EQ(p.passes[1].output, 1);
  EXPECT_EQ(p.passes[1].inputs[0].kind, InputKind::none);  // main does not read the scene it draws
  EXPECT_EQ(p.passes[2].define, "POSTPROCESSING");
  EXPECT_EQ(p.passes[2].kind, PassKind::image);
  EXPECT_EQ(p.passes[2].inputs[0].uniform, "u_scene");
  EXPECT_EQ(p.passes[2].inputs[0].kind, InputKind::buffer);
  EXPECT_EQ(p.passes[2].inputs[0].buffer, 1);
  EXPECT_EQ(p.passes[2].inputs[1].buffer, 0);  // u_doubleBuffer0
}

TEST(GlslViewer, RefusalsNameTheirLine) {
  EXPECT_NE(error_of("void main() {\n}\nuniform vec3 u_camera;\n").find("3: u_camera"), std::string::npos);
  EXPECT_NE(error_of("uniform samplerCube u_env;\nvoid main(){}").find("1: u_env"), std::string::npos);
  EXPECT_NE(error_of("\nuniform sampler2D u_scene;\nvoid main(){}").find("2: u_scene"), std::string::npos);  // no POSTPROCESSING
  EXPECT_NE(error_of("uniform sampler2D u_sceneDepth;\n#ifdef POSTPROCESSING\n#endif\nvoid main(){}").find("1: u_sceneDepth"),
            std::string::npos);
  EXPECT_NE(error_of("uniform sampler2D u_buffer0; // 256x256\nvoid main(){\n#ifdef BUFFER_0\n#endif\n}").find("1: u_buffer0"),
            std::string::npos);
  EXPECT_NE(error_of("#ifdef BUFFER_1\n#endif\nvoid main(){}").find("BUFFER_1"), std::string::npos);
}

}  // namespace
}  // namespace ms
