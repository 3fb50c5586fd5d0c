// Issue 16 item 7, glslViewer files through the real binary: the same
// image written as a glslViewer .frag and as a Shadertoy shader renders the
// same bytes (a single pass on time, resolution and gl_FragCoord; a
// DOUBLE_BUFFER_0 feedback against a Buffer A reading itself), and what
// marchstudio does not run is one line naming file:line, exit 2, no file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/image_io.h"
#include "run.h"

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
  write_file(dir.path() / "a.glsl",
             "void mainImage(out vec4 o, in vec2 f) {\n"
             "  vec2 st = f / iResolution.xy;\n"
             "  o = vec4(st.x, st.y, abs(sin(iTime)), 1.0);\n"
             "}\n");
  const Image gv = render(dir.path() / "a.frag", dir.path() / "gv.png");
  const Image st = render(dir.path() / "a.glsl", dir.path() / "st.png");
  expect_same_bytes(gv, st);
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
