// Shadertoy's own rules for what a shader reads, through the real binary:
// a texture's texels are its file's bytes (straight alpha, one upload per
// input's settings), missing audio reads as audio that never loaded, a
// buffer or Cube A no pass writes is bound all zero (a warning; --strict:
// exit 1), and a still's iFrame is the frame a sequence draws at its time.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/image_io.h"
#include "run.h"
#include "shadertoy_json.h"
#include "test_texture.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A 2x1 RGBA PNG, no gamma or sRGB chunk: (200, 100, 50, 128), (30, 60, 250, 0).
void write_half_alpha_png(const fs::path& p) {
  static const char bytes[] =
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x02\x00\x00\x00\x01\x08\x06\x00"
      "\x00\x00\xf4\x22\x7f\x8a\x00\x00\x00\x11\x49\x44\x41\x54\x78\x9c\x63\x38\x91\x62\xd4\x20\x67\xf3\x8b\x01\x00"
      "\x0f\xd1\x03\x33\x90\x13\xf5\x5f\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82";
  write_file(p, std::string(bytes, sizeof bytes - 1));
}

std::string texture_input(int channel, const std::string& src, bool vflip, bool srgb = false) {
  return "{\"id\": " + std::to_string(10 + channel) + ", \"ctype\": \"texture\", \"channel\": " +
         std::to_string(channel) + ", \"src\": \"" + src + "\", \"sampler\": {\"filter\": \"nearest\", \"wrap\": " +
         "\"clamp\", \"vflip\": \"" + (vflip ? "true" : "false") + "\", \"srgb\": \"" + (srgb ? "true" : "false") +
         "\"}}";
}

// Renders `args` in `dir` to o.exr and reads it; a failed render fails the test.
Image render_exr(const TempDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), "render");
  args.insert(args.end(), {"-o", "o.exr"});
  const RunResult r = run_marchstudio(args, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? read_image(dir / "o.exr") : Image{};
}

TEST(ShadertoyRules, TextureTexelsAreTheFilesBytesWithStraightAlpha) {
  TempDir dir;
  write_half_alpha_png(dir / "a.png");
  // Row 0: the texel's RGB; row 1: its alpha.
  const std::string code =
      "void mainImage(out vec4 o, in vec2 f) { vec4 t = texelFetch(iChannel0, ivec2(int(f.x), 0), 0);"
      " o = vec4(f.y < 1.0 ? t.rgb : vec3(t.a), 1.0); }";
  write_file(dir / "a.json", shader({pass("Image", "image", 0, code, texture_input(0, "/media/a/a.png", false))}));
  const Image img = render_exr(dir, {"a.json", "--media-dir", ".", "--size", "2x2"});
  ASSERT_EQ(img.width, 2);
  const float want[2][4] = {{200, 100, 50, 128}, {30, 60, 250, 0}};
  for (int x = 0; x < 2; ++x) {
    for (int c = 0; c < 3; ++c)  // the image's bottom row is fragCoord.y 0.5
      EXPECT_NEAR(img.at(x, 1, c) * 255.0f, want[x][c], 0.01f) << "x " << x << " channel " << c;
    EXPECT_NEAR(img.at(x, 0, 0) * 255.0f, want[x][3], 0.01f) << "alpha of x " << x;
  }
}

TEST(ShadertoyRules, OneFileBoundTwiceGetsEachInputsOwnSampler) {
  TempDir dir;
  write_texture(dir / "t.png");  // red of texel (0, y): 160 y / 255, y 0 the file's top row
  // iChannel0 and iChannel1: vflip on and off; iChannel2: sRGB.
  const std::string code =
      "void mainImage(out vec4 o, in vec2 f) { o = vec4(texelFetch(iChannel0, ivec2(0), 0).r,"
      " texelFetch(iChannel1, ivec2(0), 0).r, texelFetch(iChannel2, ivec2(0, 1), 0).r, 1.0); }";
  const std::string inputs = texture_input(0, "/media/a/t.png", true) + ", " +
                             texture_input(1, "/media/a/t.png", false) + ", " +
                             texture_input(2, "/media/a/t.png", false, true);
  write_file(dir / "v.json", shader({pass("Image", "image", 0, code, inputs)}));
  const Image img = render_exr(dir, {"v.json", "--media-dir", ".", "--size", "1x1"});
  ASSERT_EQ(img.width, 1);
  EXPECT_NEAR(img.at(0, 0, 0), 160.0f / 255.0f, 1e-4f);  // vflip: texel row 0 is the file's bottom row
  EXPECT_NEAR(img.at(0, 0, 1), 0.0f, 1e-4f);             // as stored: the top row
  const float srgb = std::pow((160.0f / 255.0f + 0.055f) / 1.055f, 2.4f);
  EXPECT_NEAR(img.at(0, 0, 2), srgb, 2e-3f);  // decoded from sRGB
}

TEST(ShadertoyRules, MissingAudioReadsAsNeverLoaded) {
  TempDir dir;
  // Both rows of the channel, its iChannelTime and iChannelResolution.
  const std::string code =
      "void mainImage(out vec4 o, in vec2 f) { o = vec4(texelFetch(iChannel0, ivec2(f), 0).r, iChannelTime[0],"
      " iChannelResolution[0].x + iChannelResolution[0].y + iChannelResolution[0].z, iChannelTime[1]); }";
  const std::string input = "{\"id\": 1, \"ctype\": \"music\", \"channel\": 0, \"src\": \"/media/a/gone.mp3\", "
                            "\"sampler\": {\"filter\": \"linear\", \"wrap\": \"clamp\", \"vflip\": \"true\", "
                            "\"srgb\": \"false\"}}";
  write_file(dir / "m.json", shader({pass("Image", "image", 0, code, input)}));
  const RunResult r = run_marchstudio({"render", "m.json", "--media-dir", ".", "--missing-media", "black", "--size",
                                       "4x2", "--time", "3", "-o", "o.exr"},
                                      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("audio '/media/a/gone.mp3' is missing; it reads as Shadertoy's audio before it loads"),
            std::string::npos)
      << r.err;
  const Image img = read_image(dir / "o.exr");
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(img.at(x, y, 0), 0.0f) << x << "," << y;  // nothing bound: 0 in both rows
      EXPECT_EQ(img.at(x, y, 1), 0.0f) << x << "," << y;  // iChannelTime stays 0
      EXPECT_EQ(img.at(x, y, 2), 0.0f) << x << "," << y;  // no size, as an unloaded input
    }
}

const char* kZeroProbe =
    "void mainImage(out vec4 o, in vec2 f) { vec4 t = texelFetch(iChannel0, ivec2(f), 0);"
    " o = vec4(t.r + t.g + t.b + t.a + 0.25, iChannelResolution[0].x / 8.0,"
    " iChannelResolution[0].y / 8.0 + iChannelResolution[0].z / 4.0, 1.0); }";

TEST(ShadertoyRules, BufferNoPassWritesIsBoundZeroWithAWarning) {
  TempDir dir;
  write_file(dir / "b.json", shader({pass("Image", "image", 0, kZeroProbe, buffer_input(0, 258))}));
  const RunResult r =
      run_marchstudio({"render", "b.json", "--size", "4x2", "-o", "o.exr"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: Image iChannel0 reads Buffer B, which no pass writes: it reads 0"),
            std::string::npos)
      << r.err;
  const Image img = read_image(dir / "o.exr");
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(img.at(x, y, 0), 0.25f);  // every channel 0, alpha too (an unbound channel's alpha is 1)
      EXPECT_EQ(img.at(x, y, 1), 0.5f);   // iChannelResolution (4, 2, 1): the image's size
      EXPECT_EQ(img.at(x, y, 2), 0.5f);
    }
  // --strict: the warning is an error, exit 1, no file.
  const RunResult s =
      run_marchstudio({"render", "b.json", "--size", "4x2", "--strict", "-o", "s.exr"}, dir.path());
  EXPECT_EQ(s.exit_code, 1) << s.err;
  EXPECT_NE(s.err.find("Image iChannel0 reads Buffer B, which no pass writes"), std::string::npos) << s.err;
  EXPECT_FALSE(fs::exists(dir / "s.exr"));
}

TEST(ShadertoyRules, CubeANoPassWritesIsBoundZeroWithAWarning) {
  TempDir dir;
  const std::string code =
      "void mainImage(out vec4 o, in vec2 f) { vec4 t = texture(iChannel0, vec3(1.0, 0.2, 0.3));"
      " o = vec4(t.r + t.g + t.b + t.a + 0.25, iChannelResolution[0].x / 4096.0, iChannelResolution[0].z, 1.0); }";
  const std::string cube_a = "{\"id\": \"4dX3Rr\", \"ctype\": \"cubemap\", \"channel\": 0, \"src\": "
                             "\"/media/previz/cubemap00.png\"}";
  write_file(dir / "c.json", shader({pass("Image", "image", 0, code, cube_a)}));
  const RunResult r = run_marchstudio({"render", "c.json", "--size", "1x1", "-o", "o.exr"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: Image iChannel0 reads Cube A, which no pass writes: it reads 0"), std::string::npos)
      << r.err;
  const Image img = read_image(dir / "o.exr");
  EXPECT_EQ(img.at(0, 0, 0), 0.25f);
  EXPECT_EQ(img.at(0, 0, 1), 0.25f);  // (1024, 1024, 1), Shadertoy's Cube A
  EXPECT_EQ(img.at(0, 0, 2), 1.0f);
  const RunResult s = run_marchstudio({"render", "c.json", "--size", "1x1", "--strict", "-o", "s.exr"}, dir.path());
  EXPECT_EQ(s.exit_code, 1) << s.err;
  EXPECT_FALSE(fs::exists(dir / "s.exr"));
}

const char* kFrameProbe = "void mainImage(out vec4 o, in vec2 f) { o = vec4(float(iFrame) / 255.0); }";

float frame_of(const TempDir& dir, const std::string& input, const std::vector<std::string>& more) {
  std::vector<std::string> args = {input, "--size", "1x1"};
  args.insert(args.end(), more.begin(), more.end());
  const Image img = render_exr(dir, args);
  return img.pixels.empty() ? -1.0f : img.at(0, 0, 0) * 255.0f;
}

TEST(ShadertoyRules, AStillsIFrameCountsTheFramesBeforeIt) {
  TempDir dir;
  write_file(dir / "f.json", shader({pass("Image", "image", 0, kFrameProbe)}));
  write_file(dir / "f.glsl", std::string(kFrameProbe) + "\n");
  write_file(dir / "g.frag", "uniform int u_frame;\nvoid main() { gl_FragColor = vec4(float(u_frame) / 255.0); }\n");
  for (const std::string input : {"f.json", "f.glsl"}) {
    EXPECT_NEAR(frame_of(dir, input, {"--time", "1.0"}), 60.0f, 1e-3f) << input;
    EXPECT_NEAR(frame_of(dir, input, {"--time", "1.0", "--frame", "5"}), 5.0f, 1e-3f) << input;
    EXPECT_NEAR(frame_of(dir, input, {"--time", "0.5", "--fps", "30"}), 15.0f, 1e-3f) << input;
  }
  EXPECT_NEAR(frame_of(dir, "g.frag", {"--time", "1.0"}), 60.0f, 1e-3f);  // glslViewer's u_frame
  EXPECT_NEAR(frame_of(dir, "g.frag", {"--time", "1.0", "--frame", "7"}), 7.0f, 1e-3f);
}

TEST(ShadertoyRules, ATestCasesStillHasRendersIFrame) {
  TempDir dir;
  write_file(dir / "f.glsl", std::string(kFrameProbe) + "\n");
  // Frame 60, the frame Shadertoy draws at 1 s.
  ASSERT_EQ(run_marchstudio({"render", "f.glsl", "--size", "2x2", "--time", "1.0", "--frame", "60", "-o", "ref.png"},
                            dir.path())
                .exit_code,
            0);
  // No `frame`: the case at time 1 is that frame; frame = 3 is not.
  write_file(dir / "s.toml", "[[case]]\nname = \"f\"\nshader = \"f.glsl\"\ntime = 1.0\nreference = \"ref.png\"\n");
  RunResult r = run_marchstudio({"test", "s.toml"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  write_file(dir / "s.toml",
             "[[case]]\nname = \"f\"\nshader = \"f.glsl\"\ntime = 1.0\nframe = 3\nreference = \"ref.png\"\n");
  r = run_marchstudio({"test", "s.toml"}, dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

TEST(ShadertoyRules, AMultipassStillsIFrameIsItsLastReplayedFrame) {
  TempDir dir;
  // Buffer A counts the frames drawn; the Image shows that count and iFrame.
  const std::string count = "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0) + 1.0; }";
  const std::string show = "void mainImage(out vec4 o, in vec2 f) {"
                           " o = vec4(texelFetch(iChannel0, ivec2(f), 0).r / 255.0, float(iFrame) / 255.0, 0, 1); }";
  write_file(dir / "m.json", shader({pass("Buffer A", "buffer", 257, count, buffer_input(0, 257)),
                                     pass("Image", "image", 0, show, buffer_input(0, 257))}));
  const Image img = render_exr(dir, {"m.json", "--size", "1x1", "--time", "0.5"});
  ASSERT_EQ(img.width, 1);
  EXPECT_NEAR(img.at(0, 0, 0) * 255.0f, 31.0f, 1e-3f);  // frames 0..30 drawn
  EXPECT_NEAR(img.at(0, 0, 1) * 255.0f, 30.0f, 1e-3f);
  // --frame that is not that frame contradicts the replay: refused.
  RunResult r = run_marchstudio({"render", "m.json", "--time", "0.5", "--frame", "5", "-o", "x.exr"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--frame 5 conflicts with a shader that has buffers"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

}  // namespace
}  // namespace ms::test
