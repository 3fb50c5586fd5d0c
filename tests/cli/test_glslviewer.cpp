// glslViewer files through the real binary: the same
// image written as a glslViewer .frag and as a Shadertoy shader renders the
// same bytes (a single pass on time, resolution and gl_FragCoord; a
// DOUBLE_BUFFER_0 feedback against a Buffer A reading itself), and what
// marchstudio does not run is one line naming file:line, exit 2, no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io/image_io.h"
#include "run.h"
#include "test_texture.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

Image render(const fs::path& input, const fs::path& out, const std::string& time = "0.5") {
  const RunResult r = run_marchstudio({"render", input.string(), "--size", "48x32", "--time", time, "-o", out.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(out);
}

void expect_same_bytes(const Image& a, const Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_EQ(a.pixels, b.pixels) << "the two forms differ";
}

TEST(GlslViewer, SinglePassMatchesShadertoyForm) {
  TempDir dir;
  write_file(dir.path() / "a.frag",
             "#ifdef GL_ES\nprecision mediump float;\n#endif\n"
             "uniform vec2 u_resolution;\nuniform float u_time;\n"
             "void main() {\n"
             "  vec2 st = gl_FragCoord.xy / u_resolution.xy;\n"
             "  gl_FragColor = vec4(st.x, st.y, abs(sin(u_time)), 1.0);\n"
             "}\n");
  // gl_FragData[0] is the same colour.
  std::string data = read_file(dir.path() / "a.frag");
  data.replace(data.find("gl_FragColor ="), 14, "gl_FragData[0] =");
  write_file(dir.path() / "d.frag", data);
  write_file(dir.path() / "a.glsl",
             "void mainImage(out vec4 o, in vec2 f) {\n"
             "  vec2 st = f / iResolution.xy;\n"
             "  o = vec4(st.x, st.y, abs(sin(iTime)), 1.0);\n"
             "}\n");
  const Image gv = render(dir.path() / "a.frag", dir.path() / "gv.png");
  const Image st = render(dir.path() / "a.glsl", dir.path() / "st.png");
  expect_same_bytes(gv, st);
  expect_same_bytes(render(dir.path() / "d.frag", dir.path() / "d.png"), st);
  // Not trivially equal: the blue channel follows time.
  EXPECT_NEAR(gv.at(0, 0, 2), std::abs(std::sin(0.5f)), 1.0 / 255.0);
}

TEST(GlslViewer, DoubleBufferFeedbackMatchesShadertoyBuffer) {
  TempDir dir;
  // Each frame adds 1/64 to the buffer's red; the image shows it.
  write_file(dir.path() / "fb.frag",
             "uniform sampler2D u_doubleBuffer0;\nuniform vec2 u_resolution;\n"
             "void main() {\n"
             "  vec2 st = gl_FragCoord.xy / u_resolution.xy;\n"
             "#ifdef DOUBLE_BUFFER_0\n"
             "  vec4 prev = texture2D(u_doubleBuffer0, st);\n"
             "  gl_FragColor = vec4(prev.r + 1.0 / 64.0, st.x, 0.0, 1.0);\n"
             "#else\n"
             "  gl_FragColor = vec4(texture2D(u_doubleBuffer0, st).rg, 0.5, 1.0);\n"
             "#endif\n"
             "}\n");
  const std::string buffer =
      "void mainImage(out vec4 o, in vec2 f) {\\n  vec2 st = f / iResolution.xy;\\n"
      "  vec4 prev = texture(iChannel0, st);\\n  o = vec4(prev.r + 1.0 / 64.0, st.x, 0.0, 1.0);\\n}\\n";
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) {\\n  vec2 st = f / iResolution.xy;\\n"
      "  o = vec4(texture(iChannel0, st).rg, 0.5, 1.0);\\n}\\n";
  const std::string input = "{\"id\": 257, \"ctype\": \"buffer\", \"channel\": 0}";
  write_file(dir.path() / "fb.json",
             "{\"Shader\": {\"info\": {\"name\": \"fb\"}, \"renderpass\": ["
             "{\"name\": \"Buffer A\", \"type\": \"buffer\", \"code\": \"" + buffer + "\", \"inputs\": [" + input +
                 "], \"outputs\": [{\"id\": 257, \"channel\": 0}]},"
                 "{\"name\": \"Image\", \"type\": \"image\", \"code\": \"" + image + "\", \"inputs\": [" + input +
                 "], \"outputs\": []}]}}");
  // --time 0.1 at 60 fps: frames 0..6, seven steps of 1/64.
  const Image gv = render(dir.path() / "fb.frag", dir.path() / "gv.png", "0.1");
  const Image st = render(dir.path() / "fb.json", dir.path() / "st.png", "0.1");
  expect_same_bytes(gv, st);
  EXPECT_GT(gv.at(10, 10, 0), 5.0 / 64.0) << "the double buffer did not carry its state";
}


TEST(GlslViewer, TexturesFromTheCommandLineMatchShadertoyTextures) {
  TempDir dir;
  write_texture(dir.path() / "tex.png");
  write_texture(dir.path() / "other.png");
  // u_tex0 by order and a named sampler, with glslViewer's <name>Resolution.
  write_file(dir.path() / "t.frag",
             "uniform sampler2D u_tex0;\nuniform sampler2D u_mine;\nuniform vec2 u_tex0Resolution;\n"
             "uniform vec2 u_resolution;\n"
             "void main() {\n"
             "  vec2 st = gl_FragCoord.xy / u_resolution.xy * 1.5;\n"
             "  gl_FragColor = vec4(texture2D(u_tex0, st).rg, texture2D(u_mine, st.yx).b * 0.5 + u_tex0Resolution.x / 16.0, 1.0);\n"
             "}\n");
  // Shadertoy's form: both textures linear, repeat and flipped, as glslViewer loads them.
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) {\\n  vec2 st = f / iResolution.xy * 1.5;\\n"
      "  o = vec4(texture(iChannel0, st).rg, texture(iChannel1, st.yx).b * 0.5 + iChannelResolution[0].x / 16.0, 1.0);\\n}\\n";
  const std::string sampler = "\"sampler\": {\"filter\": \"linear\", \"wrap\": \"repeat\", \"vflip\": \"true\", \"srgb\": \"false\"}";
  write_file(dir.path() / "t.json",
             "{\"Shader\": {\"info\": {\"name\": \"t\"}, \"renderpass\": ["
             "{\"name\": \"Image\", \"type\": \"image\", \"code\": \"" + image + "\", \"inputs\": ["
             "{\"id\": 1, \"src\": \"/media/a/tex.png\", \"ctype\": \"texture\", \"channel\": 0, " + sampler + "},"
             "{\"id\": 2, \"src\": \"/media/a/other.png\", \"ctype\": \"texture\", \"channel\": 1, " + sampler + "}"
             "], \"outputs\": []}]}}");
  const fs::path gv_out = dir.path() / "gv.png";
  RunResult r = run_marchstudio({"render", "t.frag", "--texture", "tex.png", "--texture", "u_mine=other.png", "--strict",
                                 "--size", "48x32", "-o", gv_out.string()},
                                dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_marchstudio({"render", "t.json", "--media-dir", ".", "--size", "48x32", "-o", "st.png"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image gv = read_image(gv_out), st = read_image(dir.path() / "st.png");
  expect_same_bytes(gv, st);
  // The picture is really there: red spans the texture's texels, blue carries the 4-texel width.
  float lo = 1, hi = 0;
  for (int x = 0; x < gv.width; ++x) lo = std::min(lo, gv.at(x, 20, 0)), hi = std::max(hi, gv.at(x, 20, 0));
  EXPECT_GT(hi - lo, 0.3f);
  EXPECT_GE(gv.at(0, 0, 2), 0.25f - 1.0f / 255.0f);

  // A missing file names it and --texture; one that binds nothing is a warning --strict refuses.
  r = run_marchstudio({"render", "t.frag", "--texture", "gone.png", "--size", "8x8", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("gone.png: --texture: texture not found"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  r = run_marchstudio({"render", "t.frag", "--texture", "u_nope=tex.png", "--strict", "--size", "8x8", "-o", "x.png"},
                      dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("the shader declares no sampler2D u_nope"), std::string::npos) << r.err;
  // On a Shadertoy shader it would do nothing: an error.
  r = run_marchstudio({"render", "t.json", "--media-dir", ".", "--texture", "tex.png", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--texture has no effect"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

// POSTPROCESSING against Shadertoy's form of it: main into Buffer A, the
// Image pass reading it.
TEST(GlslViewer, PostprocessingMatchesABufferReadByTheImage) {
  TempDir dir;
  write_file(dir.path() / "pp.frag",
             "uniform sampler2D u_scene;\nuniform vec2 u_resolution;\nuniform float u_time;\nvarying vec2 v_texcoord;\n"
             "void main() {\n"
             "#ifdef POSTPROCESSING\n"
             "  vec3 c = texture2D(u_scene, v_texcoord).rgb;\n"
             "  gl_FragColor = vec4(1.0 - c.bgr, 1.0);\n"
             "#else\n"
             "  vec2 st = gl_FragCoord.xy / u_resolution.xy;\n"
             "  gl_FragColor = vec4(st, 0.5 + 0.5 * sin(u_time), 1.0);\n"
             "#endif\n"
             "}\n");
  const std::string buffer =
      "void mainImage(out vec4 o, in vec2 f) {\\n  vec2 st = f / iResolution.xy;\\n"
      "  o = vec4(st, 0.5 + 0.5 * sin(iTime), 1.0);\\n}\\n";
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) {\\n  vec3 c = texture(iChannel0, f / iResolution.xy).rgb;\\n"
      "  o = vec4(1.0 - c.bgr, 1.0);\\n}\\n";
  const std::string input = "{\"id\": 257, \"ctype\": \"buffer\", \"channel\": 0}";
  write_file(dir.path() / "pp.json",
             "{\"Shader\": {\"info\": {\"name\": \"pp\"}, \"renderpass\": ["
             "{\"name\": \"Buffer A\", \"type\": \"buffer\", \"code\": \"" + buffer + "\", \"inputs\": [], "
             "\"outputs\": [{\"id\": 257, \"channel\": 0}]},"
             "{\"name\": \"Image\", \"type\": \"image\", \"code\": \"" + image + "\", \"inputs\": [" + input +
                 "], \"outputs\": []}]}}");
  const Image gv = render(dir.path() / "pp.frag", dir.path() / "gv.png", "0.3");
  const Image st = render(dir.path() / "pp.json", dir.path() / "st.png", "0.3");
  expect_same_bytes(gv, st);
  EXPECT_GT(gv.at(0, gv.height - 1, 2), 0.9f) << "the postprocessing pass did not run (1 - red at the lower left)";
}

TEST(GlslViewer, RefusedFeatureIsOneLineAtItsLine) {
  TempDir dir;
  write_file(dir.path() / "cam.frag",
             "uniform vec2 u_resolution;\n"
             "uniform vec3 u_camera;\n"
             "void main() { gl_FragColor = vec4(u_camera, 1.0); }\n");
  const fs::path out = dir.path() / "cam.png";
  const RunResult r = run_marchstudio({"render", (dir.path() / "cam.frag").string(), "--size", "8x8", "-o", out.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cam.frag:2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("u_camera"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace ms::test
