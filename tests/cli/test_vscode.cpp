// VS Code Shader Toy extension files through the real
// binary: a main file reading a bufferA.glsl that feeds back on "self" and
// a texture the test writes renders the same bytes as the same shader in
// Shadertoy's JSON; "Mirror" wraps as a mirrored coordinate does; the
// keyboard and #iUniform compile and take --uniform; a path outside the
// include roots is one line naming file:line, exit 2, no output.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/image_io.h"
#include "run.h"
#include "test_texture.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;


Image render(const fs::path& dir, const std::string& input, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", input, "--size", "48x32", "--time", "0.1", "--media-dir", ".", "-o", "out.png"};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(dir / "out.png");
}

std::string json(const std::string& buffer_code, const std::string& buffer_inputs, const std::string& image_code,
                 const std::string& image_inputs) {
  std::string passes;
  if (!buffer_code.empty())
    passes = "{\"name\": \"Buffer A\", \"type\": \"buffer\", \"code\": \"" + buffer_code + "\", \"inputs\": [" + buffer_inputs +
             "], \"outputs\": [{\"id\": 257, \"channel\": 0}]},";
  return "{\"Shader\": {\"info\": {\"name\": \"j\"}, \"renderpass\": [" + passes +
         "{\"name\": \"Image\", \"type\": \"image\", \"code\": \"" + image_code + "\", \"inputs\": [" + image_inputs +
         "], \"outputs\": []}]}}";
}

TEST(VsCode, BufferWithSelfAndTextureMatchesShadertoyJson) {
  TempDir dir;
  write_texture(dir.path() / "tex.png");
  // Buffer A adds 1/64 to its red each frame; the image shows it beside the texture.
  write_file(dir.path() / "bufferA.glsl",
             "#iChannel0 \"self\"\n"
             "void mainImage(out vec4 o, in vec2 f) {\n  vec2 st = f / iResolution.xy;\n"
             "  vec4 prev = texture(iChannel0, st);\n  o = vec4(prev.r + 1.0 / 64.0, st.x, 0.0, 1.0);\n}\n");
  write_file(dir.path() / "main.glsl",
             "#iChannel0 \"file://bufferA.glsl\"\n"
             "#iChannel1 \"file://tex.png\" // the test's own texture\n"
             "void mainImage(out vec4 o, in vec2 f) {\n  vec2 st = f / iResolution.xy;\n"
             "  o = vec4(texture(iChannel0, st).rg, texture(iChannel1, st * 1.5).r, 1.0);\n}\n");
  const std::string buffer =
      "\\nvoid mainImage(out vec4 o, in vec2 f) {\\n  vec2 st = f / iResolution.xy;\\n"
      "  vec4 prev = texture(iChannel0, st);\\n  o = vec4(prev.r + 1.0 / 64.0, st.x, 0.0, 1.0);\\n}\\n";
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) {\\n  vec2 st = f / iResolution.xy;\\n"
      "  o = vec4(texture(iChannel0, st).rg, texture(iChannel1, st * 1.5).r, 1.0);\\n}\\n";
  const std::string a = "{\"id\": 257, \"ctype\": \"buffer\", \"channel\": 0}";
  const std::string tex = "{\"id\": 1, \"src\": \"/media/a/tex.png\", \"ctype\": \"texture\", \"channel\": 1, \"sampler\": "
                          "{\"filter\": \"linear\", \"wrap\": \"repeat\", \"vflip\": \"true\", \"srgb\": \"false\"}}";
  write_file(dir.path() / "j.json", json(buffer, a, image, a + "," + tex));
  const Image vs = render(dir.path(), "main.glsl");
  const Image st = render(dir.path(), "j.json");
  ASSERT_EQ(vs.width, st.width);
  EXPECT_EQ(vs.pixels, st.pixels) << "the two forms differ";
  // --time 0.1 at 60 fps: frames 0..6, seven steps of 1/64 carried by "self".
  EXPECT_NEAR(vs.at(10, 10, 0), 7.0 / 64.0, 1.0 / 255.0);
  float lo = 1, hi = 0;
  for (int x = 0; x < vs.width; ++x) lo = std::min(lo, vs.at(x, 20, 2)), hi = std::max(hi, vs.at(x, 20, 2));
  EXPECT_GT(hi - lo, 0.3f) << "the texture is not there";
}

// The extension's other entry point: void main() writing gl_FragColor from
// gl_FragCoord, in the main file and in a buffer fed back on itself, gives
// the bytes of the same shader written with mainImage.
TEST(VsCode, VoidMainFilesMatchTheMainImageForm) {
  TempDir dir;
  write_file(dir.path() / "b.glsl",
             "#iChannel0 \"self\"\n"
             "void main() {\n  vec2 st = gl_FragCoord.xy / iResolution.xy;\n"
             "  gl_FragColor = vec4(texture(iChannel0, st).r + 1.0 / 64.0, st.x, 0.0, 1.0);\n}\n");
  write_file(dir.path() / "m.glsl",
             "#iChannel0 \"file://b.glsl\"\n"
             "void main() {\n  vec2 st = gl_FragCoord.xy / iResolution.xy;\n"
             "  gl_FragColor = vec4(texture(iChannel0, st).rg, 0.5 + 0.5 * sin(iTime * 3.0), 1.0);\n}\n");
  write_file(dir.path() / "b2.glsl",
             "#iChannel0 \"self\"\n"
             "void mainImage(out vec4 o, in vec2 f) {\n  vec2 st = f / iResolution.xy;\n"
             "  o = vec4(texture(iChannel0, st).r + 1.0 / 64.0, st.x, 0.0, 1.0);\n}\n");
  write_file(dir.path() / "m2.glsl",
             "#iChannel0 \"file://b2.glsl\"\n"
             "void mainImage(out vec4 o, in vec2 f) {\n  vec2 st = f / iResolution.xy;\n"
             "  o = vec4(texture(iChannel0, st).rg, 0.5 + 0.5 * sin(iTime * 3.0), 1.0);\n}\n");
  const Image a = render(dir.path(), "m.glsl"), b = render(dir.path(), "m2.glsl");
  ASSERT_EQ(a.width, b.width);
  EXPECT_EQ(a.pixels, b.pixels) << "main() and mainImage() forms differ";
  EXPECT_NEAR(a.at(10, 10, 0), 7.0 / 64.0, 1.0 / 255.0) << "the buffer did not feed back";
}

TEST(VsCode, MirrorWrapMatchesAMirroredCoordinate) {
  TempDir dir;
  write_texture(dir.path() / "tex.png");
  // Nearest texels at st + 1 mirrored are those at 1 - st repeated.
  write_file(dir.path() / "m.glsl",
             "#iChannel0 \"file://tex.png\"\n#iChannel0::WrapMode \"Mirror\"\n"
             "#iChannel0::MinFilter \"Nearest\"\n#iChannel0::MagFilter \"Nearest\"\n"
             "void mainImage(out vec4 o, in vec2 f) { o = vec4(texture(iChannel0, f / iResolution.xy + 1.0).rgb, 1.0); }\n");
  const std::string image = "void mainImage(out vec4 o, in vec2 f) { o = vec4(texture(iChannel0, 1.0 - f / iResolution.xy).rgb, 1.0); }";
  write_file(dir.path() / "j.json",
             json("", "", image,
                  "{\"id\": 1, \"src\": \"/media/a/tex.png\", \"ctype\": \"texture\", \"channel\": 0, \"sampler\": "
                  "{\"filter\": \"nearest\", \"wrap\": \"repeat\", \"vflip\": \"true\", \"srgb\": \"false\"}}"));
  const Image vs = render(dir.path(), "m.glsl");
  const Image st = render(dir.path(), "j.json");
  EXPECT_EQ(vs.pixels, st.pixels) << "Mirror did not mirror";
  EXPECT_NE(vs.at(0, 0, 0), vs.at(47, 0, 0));  // not flat
}

TEST(VsCode, KeyboardAndUniformRun) {
  TempDir dir;
  write_file(dir.path() / "k.glsl",
             "#iKeyboard\n#iUniform float gain = 0.25 in { 0.0, 1.0 }\n"
             "void mainImage(out vec4 o, in vec2 f) {\n"
             "  o = vec4(gain, isKeyDown(Key_A) || isKeyToggled(Key_Space) || isKeyReleased(Key_B) ? 1.0 : 0.0, 0.0, 1.0);\n}\n");
  Image im = render(dir.path(), "k.glsl");
  EXPECT_NEAR(im.at(0, 0, 0), 0.25, 1.0 / 255.0);
  EXPECT_EQ(im.at(0, 0, 1), 0.0f);  // no key is down in a render
  im = render(dir.path(), "k.glsl", {"--uniform", "gain=0.75"});
  EXPECT_NEAR(im.at(0, 0, 0), 0.75, 1.0 / 255.0);
}

TEST(VsCode, PathOutsideTheRootsIsOneLineExit2NoOutput) {
  TempDir dir;
  fs::create_directories(dir.path() / "proj");
  write_file(dir.path() / "secret.glsl", "void mainImage(out vec4 o, in vec2 f) { o = vec4(1.0); }\n");
  write_file(dir.path() / "proj" / "m.glsl",
             "// reads outside its directory\n#iChannel0 \"file://../secret.glsl\"\n"
             "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel0, f); }\n");
  const RunResult r = run_marchstudio({"render", "proj/m.glsl", "--size", "8x8", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("m.glsl:2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("#iChannel0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is outside the directories includes may read"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
  // A URL is refused the same way.
  write_file(dir.path() / "proj" / "u.glsl", "#iChannel0 \"https://example.com/a.png\"\n"
                                              "void mainImage(out vec4 o, in vec2 f) { o = vec4(1.0); }\n");
  const RunResult u = run_marchstudio({"render", "proj/u.glsl", "--size", "8x8", "-o", "x.png"}, dir.path());
  EXPECT_EQ(u.exit_code, 2);
  EXPECT_NE(u.err.find("u.glsl:1"), std::string::npos) << u.err;
  EXPECT_NE(u.err.find("is not fetched"), std::string::npos) << u.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

}  // namespace
}  // namespace ms::test
