// render --dispatch compute of Shadertoy inputs: the Image pass
// runs as a compute shader (its texture() calls at LOD 0, the same texel on
// inputs without mip maps), buffer passes stay fragment passes, and the
// pixels equal the fragment pass's: a bare shader at spp 1 and 4, and a
// project whose Image pass reads a feedback buffer and a texture. Derivative
// calls, and implicit-LOD lookups of a mipmapped input, are refused in one
// line at their file:line with no file written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "image_diff.h"
#include "io/image_io.h"
#include "run.h"
#include "shadertoy_json.h"
#include "test_texture.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// Renders `input` (in dir) with `dispatch`; the image (empty on failure).
Image render(const TempDir& dir, const std::string& input, const std::string& dispatch, const std::string& out,
             std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", input, "--size", "96x54", "--dispatch", dispatch,
                                   "--media-dir", dir.path().string(), "-o", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args, dir.path());
  EXPECT_EQ(r.exit_code, 0) << input << " " << dispatch << ": " << r.err;
  if (r.exit_code != 0) return {};
  return read_image(dir / out);
}

std::string sampler(const std::string& filter) {
  return "{\"filter\": \"" + filter + "\", \"wrap\": \"repeat\", \"vflip\": \"true\"}";
}

// A small raymarched sphere over a pattern: loops, branches, transcendental
// functions, the jitter through fragCoord.
const char* kToy =
    "float map(vec3 p) { return length(p - vec3(0.0, 0.0, 3.0)) - 1.0 + 0.05 * sin(8.0 * p.x + iTime); }\n"
    "void mainImage(out vec4 o, in vec2 f) {\n"
    "  vec2 uv = (2.0 * f - iResolution.xy) / iResolution.y;\n"
    "  vec3 rd = normalize(vec3(uv, 1.5));\n"
    "  float t = 0.0;\n"
    "  for (int i = 0; i < 64; ++i) { float d = map(rd * t); if (d < 1e-3) break; t += d; }\n"
    "  vec3 c = t < 10.0 ? vec3(0.5 + 0.5 * cos(t * 3.0 + vec3(0, 2, 4))) : vec3(fract(uv.x * 4.0) * 0.2);\n"
    "  o = vec4(c, 1.0);\n"
    "}\n";

TEST(DispatchShadertoy, ImagePassEqualsFragment) {
  TempDir dir;
  write_file(dir / "toy.glsl", kToy);
  for (const std::string spp : {"1", "4"}) {
    const Image f = render(dir, "toy.glsl", "fragment", "f" + spp + ".png", {"--spp", spp, "--time", "0.5"});
    const Image c = render(dir, "toy.glsl", "compute", "c" + spp + ".png", {"--spp", spp, "--time", "0.5"});
    EXPECT_LE(max_diff(f, c), 1.0 / 255 + 1e-6) << "spp " << spp;
  }
  const Image f = render(dir, "toy.glsl", "fragment", "f.exr", {"--spp", "4"});
  const Image c = render(dir, "toy.glsl", "compute", "c.exr", {"--spp", "4"});
  EXPECT_LE(max_diff(f, c), 1e-5);
}

// Buffer A feeds itself (a counter plus a pattern, 10 frames at --time
// 0.15 and 60 fps); the Image pass reads it and a 4x2 texture with
// texture(), linearly filtered and repeated, at uvs between texels.
TEST(DispatchShadertoy, BuffersAndTexturesEqualFragment) {
  TempDir dir;
  write_texture(dir / "tex.png");
  const std::string buffer_a =
      "void mainImage(out vec4 o, in vec2 f) {\n"
      "  o = texelFetch(iChannel0, ivec2(f), 0) + vec4(1.0 / 255.0, 0.01 * sin(f.x * 0.3), 0.0, 0.0);\n"
      "}\n";
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) {\n"
      "  vec2 uv = f / iResolution.xy;\n"
      "  vec4 a = texture(iChannel0, uv * 1.3);\n"
      "  vec4 t = texture(iChannel1, uv * 2.7 + 0.1);\n"
      "  o = vec4(a.r * 8.0 + t.r, a.g + t.g, t.b, 1.0);\n"
      "}\n";
  const std::string buf_in = "{\"id\": 257, \"ctype\": \"buffer\", \"channel\": 0, \"sampler\": " + sampler("linear") + "}";
  const std::string tex_in =
      "{\"id\": 9, \"src\": \"/media/a/tex.png\", \"ctype\": \"texture\", \"channel\": 1, \"sampler\": " +
      sampler("linear") + "}";
  write_file(dir / "p.json", shader({pass("Buffer A", "buffer", 257, buffer_a, buf_in),
                                     pass("Image", "image", 0, image, buf_in + ", " + tex_in)}));
  const Image f = render(dir, "p.json", "fragment", "f.exr", {"--time", "0.15"});
  const Image c = render(dir, "p.json", "compute", "c.exr", {"--time", "0.15"});
  EXPECT_LE(max_diff(f, c), 1e-5);
  ASSERT_FALSE(f.pixels.empty());
  EXPECT_GT(f.pixels[0], 9.0f * 8.0f / 255.0f);  // the buffer counted its frames
}

// One line, exit 2, no file; the line names `where`.
void expect_refused(const TempDir& dir, const std::string& input, const std::string& what, const std::string& where) {
  const RunResult r = run_marchstudio({"render", input, "--size", "16x16", "--dispatch", "compute", "--media-dir",
                                       dir.path().string(), "-o", "x.png"},
                                      dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(DispatchShadertoy, DerivativesAreRefusedAtTheirLine) {
  TempDir dir;
  write_file(dir / "d.glsl",
             "// fwidth( in a comment is no call\n"
             "void mainImage(out vec4 o, in vec2 f) {\n"
             "  o = vec4(fwidth(f.x), 0.0, 0.0, 1.0);\n"
             "}\n");
  expect_refused(dir, "d.glsl", "calls fwidth()", "d.glsl:3");
  // The fragment pass still draws it.
  EXPECT_FALSE(render(dir, "d.glsl", "fragment", "f.png").pixels.empty());
}

TEST(DispatchShadertoy, ImplicitLodOfAMipmappedInputIsRefusedAtItsLine) {
  TempDir dir;
  write_texture(dir / "tex.png");
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) {\n"
      "  vec2 uv = f / iResolution.xy;\n"
      "  o = textureLod(iChannel0, uv, 0.0) + texture(iChannel0, uv);\n"
      "}\n";
  write_file(dir / "img.glsl", image);
  write_file(dir / "m.toml",
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\n"
             "iChannel0 = { texture = \"tex.png\", filter = \"mipmap\" }\n");
  expect_refused(dir, "m.toml", "texture() takes its mip level from derivatives", "img.glsl:3");
  // Without mip maps the same call is rewritten to LOD 0 and draws.
  write_file(dir / "l.toml",
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\n"
             "iChannel0 = { texture = \"tex.png\", filter = \"linear\", wrap = \"repeat\" }\n");
  const Image f = render(dir, "l.toml", "fragment", "f.exr");
  const Image c = render(dir, "l.toml", "compute", "c.exr");
  EXPECT_LE(max_diff(f, c), 1e-5);
}

}  // namespace
}  // namespace ms::test
