// Typed channels and volume inputs, through the real binary:
// Shadertoy's two 3D noise volumes stand in as generated 32^3 textures
// whose every voxel the test computes from the same generator
// (volume_noise_byte), read with texelFetch and texture(); a channel's
// sampler type follows what is bound; bad volumes are one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/image_io.h"
#include "pipeline/project_passes.h"
#include "run.h"
#include "shadertoy_json.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const char* kGray3D = "/media/a/27012b4eadd0c3ce12498b867058e4f717ce79e10a99568cca461682d84a4b04.bin";
const char* kRgba3D = "/media/a/aea6b99da1d53055107966b59ac5444fc8bc7b3ce2d0bbb6a4a3cbae1d97f3aa.bin";

std::string volume_input(int channel, const std::string& src, const std::string& sampler = "") {
  return "{\"id\": 30, \"ctype\": \"volume\", \"channel\": " + std::to_string(channel) + ", \"src\": \"" + src + "\"" +
         (sampler.empty() ? "" : ", \"sampler\": " + sampler) + "}";
}
// One Image pass, or a Buffer A (writing 0.25 everywhere) then the Image pass.
std::string image_json(const std::string& code, const std::string& inputs, bool with_buffer = false) {
  std::string s = "{\"Shader\": {\"info\": {\"name\": \"v\"}, \"renderpass\": [";
  if (with_buffer)
    s += "{\"name\": \"Buffer A\", \"type\": \"buffer\", \"code\": \"void mainImage(out vec4 o, in vec2 f) { o = "
         "vec4(0.25); }\", \"inputs\": [], \"outputs\": [{\"id\": 257, \"channel\": 0}]}, ";
  return s + "{\"name\": \"Image\", \"type\": \"image\", \"code\": \"" + json_escape(code) + "\", \"inputs\": [" + inputs +
         "], \"outputs\": []}]}}";
}

// Pixel x (of a 32x1 image) reads voxel (x, 7x mod 32, 13x + 5 mod 32).
int vy(int x) { return (7 * x) % 32; }
int vz(int x) { return (13 * x + 5) % 32; }
const char* kVoxelOfPixel = "ivec3 voxel(vec2 f) { int x = int(f.x); return ivec3(x, (7 * x) % 32, (13 * x + 5) % 32); }\n";

float expected(int x, int c) { return static_cast<float>(volume_noise_byte(x, vy(x), vz(x), c, 32)) / 255.0f; }

Image render(const TempDir& dir, const std::string& file, std::vector<std::string> args) {
  std::vector<std::string> all = {"render", file, "--size", "32x1", "--missing-media", "noise", "-o", "o.exr"};
  all.insert(all.end(), args.begin(), args.end());
  const RunResult r = run_marchstudio(all, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  return read_image(dir / "o.exr");
}

TEST(ShadertoyVolume, RgbaNoiseTexelsMatchTheGenerator) {
  TempDir dir;
  // rgb of the voxel, and its alpha in a second render.
  for (int pass = 0; pass < 2; ++pass) {
    const std::string pick = pass == 0 ? "t.rgb" : "vec3(t.a, 0.0, 0.0)";
    write_file(dir / "v.json", image_json(std::string(kVoxelOfPixel) +
                                              "void mainImage(out vec4 o, in vec2 f) { vec4 t = texelFetch(iChannel0, "
                                              "voxel(f), 0); o = vec4(" + pick + ", 1.0); }",
                                          volume_input(0, kRgba3D)));
    const Image img = render(dir, "v.json", {});
    ASSERT_EQ(img.width, 32);
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < (pass == 0 ? 3 : 1); ++c)
        EXPECT_FLOAT_EQ(img.at(x, 0, c), expected(x, pass == 0 ? c : 3)) << "x " << x << " c " << c;
  }
}

TEST(ShadertoyVolume, TextureAtVoxelCentresRepeatsAndHasMips) {
  TempDir dir;
  // texture() at the voxel's centre shifted by one whole period: the repeat
  // wrap brings it back, and linear filtering at a centre is the texel.
  const std::string centre = std::string(kVoxelOfPixel) +
                             "vec3 at(vec2 f) { return (vec3(voxel(f)) + 0.5) / 32.0 + vec3(1.0, -1.0, 2.0); }\n";
  write_file(dir / "lin.json", image_json(centre + "void mainImage(out vec4 o, in vec2 f) { o = vec4(texture(iChannel0, "
                                                   "at(f)).rgb, 1.0); }",
                                          volume_input(0, kRgba3D, "{\"filter\": \"linear\", \"wrap\": \"repeat\"}")));
  Image img = render(dir, "lin.json", {});
  ASSERT_EQ(img.width, 32);
  for (int x = 0; x < 32; ++x)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(x, 0, c), expected(x, c), 1e-6) << "x " << x << " c " << c;

  // Shadertoy's default sampler (mipmap, repeat): level 0 is the voxels,
  // the last level (1x1x1) their mean, within the rounding of 5 halvings
  // to 8 bits (llvmpipe's rounding drifts up by about 3/255). Without a mip
  // chain, level 5 would read the level-0 voxel: noise all over 0..1.
  write_file(dir / "mip.json", image_json(centre + "void mainImage(out vec4 o, in vec2 f) { o = vec4(textureLod(iChannel0, "
                                                   "at(f), 0.0).r, textureLod(iChannel0, at(f), 5.0).rg, 1.0); }",
                                          volume_input(0, kRgba3D)));
  img = render(dir, "mip.json", {});
  ASSERT_EQ(img.width, 32);
  double mean[2] = {0, 0};
  for (int z = 0; z < 32; ++z)
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        for (int c = 0; c < 2; ++c) mean[c] += volume_noise_byte(x, y, z, c, 32) / 255.0 / 32768.0;
  for (int x = 0; x < 32; ++x) {
    EXPECT_NEAR(img.at(x, 0, 0), expected(x, 0), 1e-6) << x;
    EXPECT_NEAR(img.at(x, 0, 1), mean[0], 6.0 / 255.0) << x;
    EXPECT_NEAR(img.at(x, 0, 2), mean[1], 6.0 / 255.0) << x;
  }
}

TEST(ShadertoyVolume, GrayNoiseIsOneChannelAndResolutionIs32) {
  TempDir dir;
  // A volume next to a buffer in one pass: each channel gets its own type.
  write_file(dir / "g.json",
             image_json(std::string(kVoxelOfPixel) +
                            "void mainImage(out vec4 o, in vec2 f) { vec4 t = texelFetch(iChannel0, voxel(f), 0);\n"
                            "  float b = texelFetch(iChannel1, ivec2(f), 0).r;\n"
                            "  o = int(f.x) == 0 ? vec4(iChannelResolution[0] / 255.0, 1.0) : int(f.x) == 1 ? "
                            "vec4(t.gba, 1.0) : int(f.x) == 2 ? vec4(b, iChannelResolution[1].xy / 255.0, 1.0) : "
                            "vec4(t.r, 0.0, 0.0, 1.0); }",
                        volume_input(0, kGray3D) + ", {\"id\": 257, \"ctype\": \"buffer\", \"channel\": 1}", true));
  const Image img = render(dir, "g.json", {"--time", "0"});
  ASSERT_EQ(img.width, 32);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(img.at(0, 0, c), 32.0f / 255.0f) << c;  // (32, 32, 32)
  EXPECT_FLOAT_EQ(img.at(1, 0, 0), 0.0f);  // one channel: (v, 0, 0, 1)
  EXPECT_FLOAT_EQ(img.at(1, 0, 1), 0.0f);
  EXPECT_FLOAT_EQ(img.at(1, 0, 2), 1.0f);
  EXPECT_FLOAT_EQ(img.at(2, 0, 0), 0.25f);  // the buffer, a sampler2D beside the sampler3D
  EXPECT_FLOAT_EQ(img.at(2, 0, 1), 32.0f / 255.0f);
  EXPECT_FLOAT_EQ(img.at(2, 0, 2), 1.0f / 255.0f);
  for (int x = 3; x < 32; ++x) EXPECT_FLOAT_EQ(img.at(x, 0, 0), expected(x, 0)) << x;

  // The declarations follow the bindings.
  const RunResult r = run_marchstudio({"render", "g.json", "--missing-media", "noise", "--print-shader"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("uniform sampler3D iChannel0;"), std::string::npos);
  EXPECT_NE(r.out.find("uniform sampler2D iChannel1;"), std::string::npos);
  EXPECT_NE(r.out.find("uniform sampler2D iChannel2;"), std::string::npos);
}

TEST(ShadertoyVolume, MissingMediaPolicyAndBadVolumes) {
  TempDir dir;
  const std::string show = "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel1, vec3(f / 32.0, 0.5)); }";
  write_file(dir / "v.json", image_json(show, volume_input(1, kGray3D)));
  write_file(dir / "unknown.json", image_json(show, volume_input(1, "/media/a/0123abcd.bin")));
  write_file(dir / "nosrc.json", image_json(show, "{\"ctype\": \"volume\", \"channel\": 1}"));
  const struct {
    const char* file;
    std::string says;
  } cases[] = {
      {"v.json", std::string("v.json: Image iChannel1: volume '") + kGray3D + "' (Gray Noise 3D) is not read from files"},
      {"unknown.json", "unknown.json: Image iChannel1: volume '/media/a/0123abcd.bin' is not one of Shadertoy's volumes"},
      {"nosrc.json", "a volume input without a src"}};
  for (const auto& c : cases) {
    for (const char* policy : {"error", "noise"}) {
      if (std::string(c.file) == "v.json" && std::string(policy) == "noise") continue;
      const RunResult r = run_marchstudio({"render", c.file, "--missing-media", policy, "-o", "x.png"}, dir.path());
      EXPECT_EQ(r.exit_code, 2) << c.file << ": " << r.err;
      EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_FALSE(fs::exists(dir / "x.png"));
    }
  }
  // Black stands in with a warning, and --strict makes that an error.
  RunResult r = run_marchstudio({"render", "v.json", "--size", "2x2", "--missing-media", "black", "-o", "b.exr"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("(Gray Noise 3D): black stands in"), std::string::npos) << r.err;
  const Image b = read_image(dir / "b.exr");
  ASSERT_EQ(b.width, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(b.at(x, y, c), 0.0f);
  r = run_marchstudio({"render", "v.json", "--missing-media", "noise", "--strict", "-o", "s.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("generated noise stands in (not Shadertoy's voxels)"), std::string::npos) << r.err;
}

TEST(ShadertoyVolume, CompileErrorsStillNameTheirLine) {
  TempDir dir;
  write_file(dir / "e.json", image_json("void mainImage(out vec4 o, in vec2 f) {\n  vec4 t = texture(iChannel0, vec3(0.5));\n"
                                        "  o = t + undefined_thing;\n}",
                                        volume_input(0, kRgba3D)));
  const RunResult r = run_marchstudio({"render", "e.json", "--missing-media", "noise", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("e.json (Image):3: shader compile error"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace ms::test
