// Multipass through the real binary, with shaders whose every pixel is
// known: a feedback counter (Buffer A adds 1/255 a frame), a chain that
// tells this frame's reads from the previous frame's, each sampler mode
// against a texture of known texels, the keyboard's layout, iMouse, the
// Image pass's non-finite channels, and bad input.
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

const char* kCounterA =
    "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0) + vec4(1.0 / 255.0); }";
const char* kShowA = "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); }";

std::string counter_json() {
  return shader({pass("Buffer A", "buffer", 257, kCounterA, buffer_input(0, 257)),
                 pass("Image", "image", 0, kShowA, buffer_input(0, 257))});
}

Image render(const TempDir& dir, const std::vector<std::string>& args, const std::string& out = "o.exr") {
  std::vector<std::string> all = {"render"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"-o", out});
  const RunResult r = run_marchstudio(all, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  return read_image(dir / out);
}

TEST(Multipass, AFeedbackCounterIsExactAtEveryStill) {
  TempDir dir;
  write_file(dir / "c.json", counter_json());
  // A still at time T replays frames 0..N, N = round(T x fps): N + 1 adds.
  for (const auto& [t, fps, n] : std::vector<std::tuple<std::string, std::string, int>>{
           {"0", "60", 0}, {"0.5", "60", 30}, {"1", "24", 24}, {"0.1", "100", 10}}) {
    const Image img = render(dir, {"c.json", "--size", "4x3", "--time", t, "--fps", fps});
    ASSERT_EQ(img.width, 4);
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) EXPECT_FLOAT_EQ(img.at(x, y, 0), static_cast<float>(n + 1) / 255.0f) << t << " " << fps;
  }
}

TEST(Multipass, SameFrameAndPreviousFrameReads) {
  TempDir dir;
  // A: r = iFrame, g = B as it stands (B runs after A: last frame's);
  // B: r = A (A runs first: this frame's). Image: (A.r, A.g, B.r).
  const std::string a = "void mainImage(out vec4 o, in vec2 f) { o = vec4(float(iFrame) / 255.0, "
                        "texelFetch(iChannel0, ivec2(f), 0).r, 0.0, 1.0); }";
  const std::string b = "void mainImage(out vec4 o, in vec2 f) { o = vec4(texelFetch(iChannel0, ivec2(f), 0).r, 0.0, 0.0, 1.0); }";
  const std::string img = "void mainImage(out vec4 o, in vec2 f) { vec4 a = texelFetch(iChannel0, ivec2(f), 0); "
                          "o = vec4(a.r, a.g, texelFetch(iChannel1, ivec2(f), 0).r, 1.0); }";
  write_file(dir / "chain.json",
             shader({pass("Buffer B", "buffer", 258, b, buffer_input(0, 257)),
                     pass("Buffer A", "buffer", 257, a, buffer_input(0, 258)),
                     pass("Image", "image", 0, img, buffer_input(0, 257) + ", " + buffer_input(1, 258))}));
  const Image out = render(dir, {"chain.json", "--size", "2x2", "--time", "5", "--fps", "1"});
  ASSERT_EQ(out.width, 2);
  EXPECT_FLOAT_EQ(out.at(0, 0, 0), 5.0f / 255.0f);  // A at frame 5
  EXPECT_FLOAT_EQ(out.at(0, 0, 1), 4.0f / 255.0f);  // B as of frame 4, read by A in frame 5
  EXPECT_FLOAT_EQ(out.at(0, 0, 2), 5.0f / 255.0f);  // B at frame 5 read A at frame 5
}

TEST(Multipass, ATomlWithPassesEqualsTheJson) {
  TempDir dir;
  write_file(dir / "c.json", counter_json());
  write_file(dir / "a.glsl", kCounterA);
  write_file(dir / "img.glsl", kShowA);
  write_file(dir / "c.toml",
             "[scene]\nname = \"counter\"\n[render]\nwidth = 5\nheight = 4\ntime = 0.25\n"
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = { buffer = \"A\" }\n"
             "[[passes]]\ntype = \"buffer\"\nbuffer = \"A\"\nfile = \"a.glsl\"\niChannel0 = { buffer = \"A\" }\n");
  const Image t = render(dir, {"c.toml"}, "t.exr");
  const Image j = render(dir, {"c.json", "--size", "5x4", "--time", "0.25"}, "j.exr");
  ASSERT_EQ(t.pixels.size(), j.pixels.size());
  EXPECT_EQ(t.pixels, j.pixels);
  EXPECT_FLOAT_EQ(t.at(0, 0, 0), 16.0f / 255.0f);  // frames 0..15
}

// A 4x2 texture whose texels are known: red = 10 * (x + 4 y) / 255,
// green = x / 255, blue = y * 100 / 255. Written as a PNG by the test.
void write_ramp_texture(const fs::path& p) {
  write_texture_4x2(p, [](int x, int y) {
    return std::array<float, 3>{10.0f * (x + 4 * y) / 255.0f, x / 255.0f, y * 100.0f / 255.0f};
  });
}

// Samples iChannel0 at `uv` and shows it.
std::string sample_at(const std::string& uv) {
  return "void mainImage(out vec4 o, in vec2 f) { o = vec4(texture(iChannel0, " + uv + ").rgb, 1.0); }";
}
std::string texture_input(const std::string& sampler) {
  return "{\"id\": 9, \"src\": \"/media/a/tex.png\", \"ctype\": \"texture\", \"channel\": 0, \"sampler\": " + sampler + "}";
}

float sampled(const TempDir& dir, const std::string& uv, const std::string& sampler, int channel = 0) {
  write_file(dir / "s.json", shader({pass("Image", "image", 0, sample_at(uv), texture_input(sampler))}));
  const Image img = render(dir, {"s.json", "--size", "1x1", "--media-dir", dir.path().string()});
  return img.pixels.empty() ? -1.0f : img.at(0, 0, channel);
}

TEST(Multipass, SamplerModesAndVflipAgainstKnownTexels) {
  TempDir dir;
  write_ramp_texture(dir / "tex.png");
  const std::string nearest = "{\"filter\": \"nearest\", \"wrap\": \"clamp\", \"vflip\": \"false\"}";
  const std::string flipped = "{\"filter\": \"nearest\", \"wrap\": \"clamp\", \"vflip\": \"true\"}";
  // uv (0,0) is the texture's first row: the file's top row without vflip,
  // its bottom row with it (Shadertoy's default: the picture upright).
  EXPECT_FLOAT_EQ(sampled(dir, "vec2(0.125, 0.25)", nearest), 0.0f);
  EXPECT_FLOAT_EQ(sampled(dir, "vec2(0.125, 0.25)", flipped), 40.0f / 255.0f);
  EXPECT_FLOAT_EQ(sampled(dir, "vec2(0.625, 0.75)", nearest), 60.0f / 255.0f);
  // Wrap: past the right edge, repeat comes back to column 0, clamp stays at 3.
  EXPECT_FLOAT_EQ(sampled(dir, "vec2(1.125, 0.25)", "{\"filter\": \"nearest\", \"wrap\": \"repeat\", \"vflip\": \"false\"}"), 0.0f);
  EXPECT_FLOAT_EQ(sampled(dir, "vec2(1.125, 0.25)", nearest), 30.0f / 255.0f);
  // Linear: halfway between texels 1 and 2 of the first row.
  EXPECT_NEAR(sampled(dir, "vec2(0.5, 0.25)", "{\"filter\": \"linear\", \"wrap\": \"clamp\", \"vflip\": \"false\"}"),
              15.0f / 255.0f, 0.5f / 255.0f);
  // Mipmap level 1 is the mean of 2x2 blocks: (0 + 10 + 40 + 50) / 4 = 25.
  write_file(dir / "l.json",
             shader({pass("Image", "image", 0,
                          "void mainImage(out vec4 o, in vec2 f) { o = vec4(textureLod(iChannel0, vec2(0.25, 0.5), 1.0).rgb, 1.0); }",
                          texture_input("{\"filter\": \"mipmap\", \"wrap\": \"clamp\", \"vflip\": \"false\"}"))}));
  const Image lod = render(dir, {"l.json", "--size", "1x1", "--media-dir", dir.path().string()});
  ASSERT_FALSE(lod.pixels.empty());
  EXPECT_NEAR(lod.at(0, 0, 0), 25.0f / 255.0f, 1.0f / 255.0f);
  // sRGB: decoded to linear when sampled.
  EXPECT_NEAR(sampled(dir, "vec2(0.125, 0.75)", "{\"filter\": \"nearest\", \"wrap\": \"clamp\", \"vflip\": \"false\", \"srgb\": \"true\"}", 2),
              std::pow((100.0f / 255.0f + 0.055f) / 1.055f, 2.4f), 1e-3f);
  // iChannelResolution is the texture's size.
  write_file(dir / "r.json", shader({pass("Image", "image", 0,
                                          "void mainImage(out vec4 o, in vec2 f) { o = vec4(iChannelResolution[0] / 255.0, 1.0); }",
                                          texture_input(nearest))}));
  const Image res = render(dir, {"r.json", "--size", "1x1", "--media-dir", dir.path().string()});
  ASSERT_FALSE(res.pixels.empty());
  EXPECT_FLOAT_EQ(res.at(0, 0, 0), 4.0f / 255.0f);
  EXPECT_FLOAT_EQ(res.at(0, 0, 1), 2.0f / 255.0f);
  EXPECT_FLOAT_EQ(res.at(0, 0, 2), 1.0f / 255.0f);
}

TEST(Multipass, KeyboardMouseAndTheShadertoyEnvironment) {
  TempDir dir;
  // The keyboard is 256x3 and all zero headless; iMouse comes from --mouse;
  // HW_PERFORMANCE is 1; desktop-only keywords are free names.
  const std::string code =
      "void mainImage(out vec4 o, in vec2 f) {\n"
      "  float buffer = texelFetch(iChannel0, ivec2(65, 0), 0).r + texelFetch(iChannel0, ivec2(37, 2), 0).r;\n"
      "  float sample = iChannelResolution[0].x / 1000.0 + iChannelResolution[0].y / 10000.0;\n"
      "  o = vec4(buffer, sample, iMouse.x / 1000.0 + float(HW_PERFORMANCE) / 100.0, iMouse.w / 1000.0);\n"
      "}\n";
  write_file(dir / "k.json", shader({pass("Image", "image", 0, code,
                                          "{\"id\": 33, \"ctype\": \"keyboard\", \"channel\": 0}")}));
  const Image img = render(dir, {"k.json", "--size", "1x1", "--mouse", "100,20,-100,-20"});
  ASSERT_FALSE(img.pixels.empty());
  EXPECT_FLOAT_EQ(img.at(0, 0, 0), 0.0f);
  EXPECT_FLOAT_EQ(img.at(0, 0, 1), 0.256f + 0.0003f);
  EXPECT_FLOAT_EQ(img.at(0, 0, 2), 0.1f + 0.01f);
  EXPECT_EQ(img.nchannels(), 4);  // alpha is 1 whatever the pass wrote
}

TEST(Multipass, LocalsStartAtZeroAsInWebGL) {
  TempDir dir;
  // `acc` is never initialised: WebGL starts it at 0, so it ends at 0.3.
  // Without Mesa's glsl_zero_init llvmpipe folds it to 0 (checked).
  write_file(dir / "u.glsl",
             "void mainImage(out vec4 o, in vec2 f) {\n  vec4 acc;\n  for (int i = 0; i < 3; ++i) acc += vec4(0.1);\n"
             "  o = vec4(acc.x, 0.0, 0.0, 1.0);\n}\n");
  const RunResult r = run_marchstudio({"render", "u.glsl", "--size", "2x2", "--backend", "egl", "-o", "u.exr"},
                                      dir.path(), "MESA_SHADER_CACHE_DIR='" + (dir / "cache").string() + "' ");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(read_image(dir / "u.exr").at(0, 0, 0), 0.3f, 1e-6f);
}

TEST(Multipass, NonFiniteImageChannelsConvertOneByOne) {
  TempDir dir;
  write_file(dir / "n.glsl",
             "void mainImage(out vec4 o, in vec2 f) { float z = f.x - f.x; o = vec4(z / z, 0.5, 1.0 / z, 0.0); }\n");
  const RunResult r = run_marchstudio({"render", "n.glsl", "--size", "2x2", "-o", "n.exr"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("4 of 4 pixels have NaN/Inf values"), std::string::npos) << r.err;
  const Image img = read_image(dir / "n.exr");
  EXPECT_EQ(img.at(0, 0, 0), 0.0f);  // NaN: 0, as a float-to-unorm write
  EXPECT_EQ(img.at(0, 0, 1), 0.5f);  // the other channels are kept
  EXPECT_EQ(img.at(0, 0, 2), 1.0f);  // +Inf: 1
  EXPECT_EQ(img.at(0, 0, 3), 1.0f);
  const RunResult strict = run_marchstudio({"render", "n.glsl", "--size", "2x2", "-o", "s.exr", "--strict"}, dir.path());
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "s.exr"));
}

TEST(Multipass, BadInputIsAOneLineErrorAndNoFile) {
  TempDir dir;
  write_file(dir / "malformed.json", "{\"Shader\": {\"renderpass\": [\n  {\"type\": \"image\" \"code\": \"\"}]}}");
  write_file(dir / "ctype.json", shader({pass("Image", "image", 0, kShowA, "{\"ctype\": \"hologram\", \"channel\": 0}")}));
  write_file(dir / "media.json", shader({pass("Image", "image", 0, sample_at("vec2(0.5)"), texture_input("{}"))}));
  write_file(dir / "range.json", shader({pass("Image", "image", 0, kShowA, "{\"ctype\": \"keyboard\", \"channel\": 7}")}));
  write_file(dir / "twice.json", shader({pass("Buffer A", "buffer", 257, kCounterA), pass("Buffer B", "buffer", 257, kCounterA),
                                         pass("Image", "image", 0, kShowA)}));
  write_file(dir / "mic.json", shader({pass("Image", "image", 0, kShowA, "{\"ctype\": \"mic\", \"channel\": 1}")}));
  const struct {
    const char* file;
    std::string says;
  } cases[] = {{"malformed.json", "malformed.json:2: malformed JSON at column 25"},
               {"ctype.json", "unknown input type 'hologram'"},
               {"media.json", "Image iChannel0: texture '/media/a/tex.png' is not in the media directory"},
               {"range.json", "channel 7 is out of range"},
               {"twice.json", "two passes write Buffer A"},
               {"mic.json", "Image iChannel1 reads a mic input, a live device that an offline render cannot have"}};
  for (const auto& c : cases) {
    const RunResult r = run_marchstudio({"render", c.file, "-o", "x.png"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << c.file << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
  }
  // Stand-ins are explicit, with a warning; --strict makes that an error.
  RunResult r = run_marchstudio({"render", "media.json", "--size", "2x2", "--missing-media", "noise", "-o", "x.png"},
                                dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("generated noise stands in (not Shadertoy's pixels)"), std::string::npos) << r.err;
  r = run_marchstudio({"render", "media.json", "--missing-media", "black", "--strict", "-o", "y.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  // A channel sampled with nothing bound: a warning naming it.
  write_file(dir / "unbound.glsl", "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel2, f / iResolution.xy); }\n");
  r = run_marchstudio({"render", "unbound.glsl", "--size", "2x2", "-o", "u.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("Image iChannel2 is sampled but nothing is bound to it"), std::string::npos) << r.err;
}

TEST(Multipass, ShadertoyOptionsOnAnSdfSceneAreErrors) {
  TempDir dir;
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  const std::vector<std::vector<std::string>> flags = {
      {"--mouse", "1,2,3,4"}, {"--media-dir", dir.path().string()}, {"--missing-media", "noise"}};
  for (const auto& f : flags)
    for (const char* sub : {"render", "bench"}) {
      std::vector<std::string> args = {sub, seed, "--size", "8x8"};
      if (std::string(sub) == "render") args.insert(args.end(), {"-o", "x.png"});
      else args.insert(args.end(), {"--frames", "1", "--warmup", "0"});
      args.insert(args.end(), f.begin(), f.end());
      const RunResult r = run_marchstudio(args, dir.path());
      EXPECT_EQ(r.exit_code, 2) << sub << " " << f[0] << ": " << r.err;
      EXPECT_NE(r.err.find(f[0] + " has no effect on an SDF scene"), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(dir / "x.png"));
    }
}

TEST(Multipass, BenchTimesEachPassAndPrintShaderShowsThemAll) {
  TempDir dir;
  write_file(dir / "c.json", counter_json());
  const RunResult b = run_marchstudio({"bench", "c.json", "--size", "16x16", "--frames", "3", "--warmup", "1", "--json"},
                                      dir.path());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.out.find("\"name\": \"Buffer A\""), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("\"name\": \"Image\""), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("\"cost\": null"), std::string::npos) << b.out;
  const RunResult p = run_marchstudio({"render", "c.json", "--print-shader"}, dir.path());
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_NE(p.out.find("// ==== marchstudio: pass Buffer A ===="), std::string::npos);
  EXPECT_NE(p.out.find("// ==== marchstudio: pass Image ===="), std::string::npos);
}

}  // namespace
}  // namespace ms::test
