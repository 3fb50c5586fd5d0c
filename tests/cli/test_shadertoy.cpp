// Shadertoy single-pass shaders render exactly as Shadertoy would: fragCoord
// at pixel centres with the origin bottom-left (so the image is upright),
// its uniforms, and no extra tone map or sRGB encode on the output.
#include <gtest/gtest.h>

#include <cmath>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

const char* kGradient = R"(// fragCoord and iTime straight to colour
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  fragColor = vec4(uv.x, uv.y, fract(iTime) * iResolution.z, 0.25);
}
)";

const char* kInputs = R"(void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = vec4(float(iFrame) / 100.0, iDate.w / 10.0, iTimeDelta * 60.0, 1.0)
            + 0.0 * texture(iChannel0, vec2(0.5)) + vec4(0.0, 0.0, 0.0, iMouse.x);
}
)";

TEST(Shadertoy, FragCoordResolutionAndTimeAreExact) {
  TempDir dir;
  write_file(dir / "grad.glsl", kGradient);
  RunResult r = run_marchstudio({"render", "grad.glsl", "-o", "g.exr", "--size", "16x8", "--time", "2.25"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Image img = read_image(dir / "g.exr");
  ASSERT_EQ(img.width, 16);
  ASSERT_EQ(img.height, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      EXPECT_FLOAT_EQ(img.at(x, y, 0), (x + 0.5f) / 16.0f) << x << "," << y;
      EXPECT_FLOAT_EQ(img.at(x, y, 1), (8 - y - 0.5f) / 8.0f) << "top row is the highest fragCoord.y";
      EXPECT_FLOAT_EQ(img.at(x, y, 2), 0.25f);
    }
  EXPECT_FLOAT_EQ(img.at(0, 0, 3), 1.0f) << "alpha is opaque, as on Shadertoy's canvas";
}

TEST(Shadertoy, PngIsNotEncodedTwice) {
  TempDir dir;
  write_file(dir / "grad.glsl", kGradient);
  RunResult r = run_marchstudio({"render", "grad.glsl", "-o", "g.png", "--size", "16x8"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Image img = read_image(dir / "g.png");
  for (int x = 0; x < 16; ++x)
    EXPECT_NEAR(img.at(x, 0, 0), (x + 0.5f) / 16.0f, 0.5f / 255.0f + 1e-6f) << x;
}

TEST(Shadertoy, FrameDateAndChannelsAreDefined) {
  TempDir dir;
  write_file(dir / "in.glsl", kInputs);
  RunResult r = run_marchstudio({"render", "in.glsl", "-o", "i.exr", "--size", "4x4", "--time", "3", "--frame", "42"},
                                dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Image img = read_image(dir / "i.exr");
  EXPECT_FLOAT_EQ(img.at(1, 1, 0), 0.42f);
  EXPECT_FLOAT_EQ(img.at(1, 1, 1), 0.3f);  // iDate.w = seconds of the day = iTime, deterministic
  EXPECT_NEAR(img.at(1, 1, 2), 1.0f, 1e-6f);
}

TEST(Shadertoy, CompileErrorNamesTheUserFileAndLine) {
  TempDir dir;
  write_file(dir / "bad.glsl", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n  c.x = undefined_thing;\n}\n");
  RunResult r = run_marchstudio({"render", "bad.glsl", "-o", "b.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.glsl:3:"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.png"));
}

TEST(Shadertoy, SceneWrappedShaderRendersIdentically) {
  // The same code, once as a bare .glsl and once wrapped in a scene file that
  // supplies size, spp and time: the two images agree (tolerance 1e-6).
  TempDir dir;
  write_file(dir / "rings.glsl", R"(void mainImage(out vec4 o, in vec2 f) {
  vec2 p = (2.0 * f - iResolution.xy) / iResolution.y;
  float r = length(p);
  o = vec4(0.5 + 0.5 * sin(20.0 * r - 3.0 * iTime), fract(p.x * 3.0), step(0.5, r), 1.0);
}
)");
  write_file(dir / "wrap.toml", "[scene]\nshadertoy = \"rings.glsl\"\n[render]\nwidth = 48\nheight = 32\n"
                                "spp = 4\ntime = 1.5\n");
  RunResult a = run_marchstudio({"render", "wrap.toml", "-o", "a.exr"}, dir.path());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  RunResult b = run_marchstudio({"render", "rings.glsl", "-o", "b.exr", "--size", "48x32", "--spp", "4", "--time", "1.5"},
                                dir.path());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  Image ia = read_image(dir / "a.exr"), ib = read_image(dir / "b.exr");
  ASSERT_EQ(ia.width, 48);
  ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
  double max_err = 0;
  for (size_t i = 0; i < ia.pixels.size(); ++i) max_err = std::max(max_err, double(std::abs(ia.pixels[i] - ib.pixels[i])));
  EXPECT_LE(max_err, 1e-6);
  // And the time really reached the shader: another time gives another image.
  RunResult c = run_marchstudio({"render", "rings.glsl", "-o", "c.exr", "--size", "48x32", "--spp", "4", "--time", "0"},
                                dir.path());
  ASSERT_EQ(c.exit_code, 0) << c.err;
  Image ic = read_image(dir / "c.exr");
  double diff = 0;
  for (size_t i = 0; i < ia.pixels.size(); ++i) diff += std::abs(ia.pixels[i] - ic.pixels[i]);
  EXPECT_GT(diff / ia.pixels.size(), 0.01);
}

TEST(Shadertoy, DefinesAreInjected) {
  TempDir dir;
  write_file(dir / "d.glsl", "#ifndef LEVEL\n#define LEVEL 0.0\n#endif\n"
                             "void mainImage(out vec4 c, in vec2 f) { c = vec4(LEVEL, 0.0, 0.0, 1.0); }\n");
  RunResult r = run_marchstudio({"render", "d.glsl", "-o", "d.exr", "--size", "2x2", "-D", "LEVEL=0.75"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FLOAT_EQ(read_image(dir / "d.exr").at(0, 0, 0), 0.75f);
  r = run_marchstudio({"render", "d.glsl", "-o", "e.exr", "--size", "2x2", "-D", "9bad=1"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("-D"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "e.exr"));
}

TEST(Shadertoy, CanUseTheSdfLibrary) {
  // primitives.glsl and operators.glsl need no scene uniforms, so a plain
  // Shadertoy shader may include them from sdf_shaders/.
  TempDir dir;
  write_file(dir / "lib.glsl", R"(#include "primitives.glsl"
#include "operators.glsl"
void mainImage(out vec4 o, in vec2 f) {
  vec3 p = vec3((2.0 * f - iResolution.xy) / iResolution.y, 0.0);
  float d = opSmoothUnion(sdSphere(p - vec3(0.3, 0.0, 0.0), 0.4), sdBox(p + vec3(0.3, 0.0, 0.0), vec3(0.3)), 0.1);
  o = vec4(d < 0.0 ? 1.0 : 0.0, saturate(d), 0.0, 1.0);
}
)");
  RunResult r = run_marchstudio({"render", "lib.glsl", "-o", "l.exr", "--size", "32x16"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Image img = read_image(dir / "l.exr");
  EXPECT_FLOAT_EQ(img.at(16, 8, 0), 1.0f) << "the centre lies inside the blend";
  EXPECT_FLOAT_EQ(img.at(0, 0, 0), 0.0f) << "a corner lies outside";
}

TEST(Shadertoy, NotAShadertoyShaderIsRejected) {
  TempDir dir;
  write_file(dir / "x.glsl", "float f() { return 1.0; }\n");
  RunResult r = run_marchstudio({"render", "x.glsl", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("mainImage"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
