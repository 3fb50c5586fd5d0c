// VS Code Shader Toy extension files (importers/vscode.h): detection, each
// directive and channel setting, the extension's pass order, "self", the
// keyboard, #iUniform, and refusals at their line. Files in a temp dir; no GL.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "files.h"
#include "shader/scene_params.h"
#include "importers/vscode.h"

namespace ms {
namespace {
namespace fs = std::filesystem;

struct Dir {
  test::TempDir tmp;
  const fs::path path = tmp.path();
  fs::path put(const std::string& name, const std::string& text) const {
    const fs::path p = path / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  ShaderProject load(const std::string& name) const {
    std::ifstream in(path / name, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return load_vscode(text, path / name, {path});
  }
  std::string error(const std::string& name) const {
    try {
      load(name);
    } catch (const Error& e) {
      return fs::path(e.info().file).filename().string() + ":" + std::to_string(e.info().line) + ": " +
             (e.info().what.find(e.info().key) == std::string::npos ? e.info().key + ": " : "") + e.info().what;
    }
    return "no error";
  }
};

const std::string kImage = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";

TEST(VsCode, RecognisedByADirectiveAtLineStart) {
  EXPECT_TRUE(looks_like_vscode("#iChannel0 \"file://a.png\"\n" + kImage));
  EXPECT_TRUE(looks_like_vscode("  #iKeyboard\n" + kImage));
  EXPECT_TRUE(looks_like_vscode("#iUniform float k = 1.0\n" + kImage));
  EXPECT_TRUE(looks_like_vscode("# iChannel3::WrapMode \"Clamp\"\n" + kImage));
  EXPECT_FALSE(looks_like_vscode("// #iChannel0 \"file://a.png\"\n" + kImage));
  EXPECT_FALSE(looks_like_vscode("/*\n#iKeyboard\n*/\n" + kImage));
  EXPECT_FALSE(looks_like_vscode("#include \"a.glsl\"\n#define iChannel0x 1\n" + kImage));
  EXPECT_FALSE(looks_like_vscode("#ifdef iChannel0\n#endif\n" + kImage));
}

TEST(VsCode, BuffersRunAfterWhatTheyReadMainLast) {
  Dir d;
  // main reads b1 (which reads b2) then b3; b2 also reads b1 (a cycle: read once).
  d.put("main.glsl", "#iChannel0 \"file://b1.glsl\"\n#iChannel1 \"file://sub/b3.glsl\"\n" + kImage);
  d.put("b1.glsl", "#iChannel2 \"file://b2.glsl\"\n" + kImage);
  d.put("b2.glsl", "#iChannel0 \"file://b1.glsl\"\n#iChannel1 \"self\"\n" + kImage);
  d.put("sub/b3.glsl", "#iChannel0 \"file://../b2.glsl\"\n" + kImage);
  const ShaderProject p = d.load("main.glsl");
  ASSERT_EQ(p.passes.size(), 4u);
  EXPECT_EQ(p.passes[0].file.filename(), "b2.glsl");
  EXPECT_EQ(p.passes[0].name, "Buffer A");
  EXPECT_EQ(p.passes[1].file.filename(), "b1.glsl");
  EXPECT_EQ(p.passes[2].file.filename(), "b3.glsl");
  EXPECT_EQ(p.passes[3].kind, PassKind::image);
  EXPECT_EQ(p.passes[3].inputs[0].buffer, 1);
  EXPECT_EQ(p.passes[3].inputs[1].buffer, 2);
  EXPECT_EQ(p.passes[0].inputs[0].buffer, 1);   // b2 reads b1 as it stands
  EXPECT_EQ(p.passes[0].inputs[1].buffer, 0);   // self: its own previous frame
  EXPECT_EQ(p.passes[2].inputs[0].buffer, 0);   // ../b2.glsl from sub/
  EXPECT_EQ(p.passes[1].inputs[2].kind, InputKind::buffer);
  EXPECT_EQ(p.passes[0].inputs[0].sampler.wrap, TexWrap::clamp);  // buffers: linear, clamp
  // Directive lines are blank; the line count stays.
  EXPECT_EQ(p.passes[3].code, "\n\n" + kImage);
}

TEST(VsCode, TexturesTakeTheExtensionsSamplerAndSettings) {
  Dir d;
  d.put("t.png", "not decoded here");
  d.put("tune.ogg", "x");
  d.put("m.glsl",
        "#iChannel0 \"file://t.png\" // a comment after\n"
        "#iChannel0::MinFilter \"Nearest\"\n#iChannel0::MagFilter \"Nearest\"\n#iChannel0::WrapMode \"Mirror\"\n"
        "#iChannel1 \"t.png\"\n"
        "#iChannel2 \"file://sky_{}.jpg\"\n#iChannel2::Type \"CubeMap\"\n"
        "#iChannel3 \"file://tune.ogg\"\n" + kImage);
  const ShaderProject p = d.load("m.glsl");
  ASSERT_EQ(p.passes.size(), 1u);
  const auto& in = p.passes[0].inputs;
  EXPECT_EQ(in[0].kind, InputKind::texture);
  EXPECT_EQ(in[0].file, d.path / "t.png");
  EXPECT_EQ(in[0].sampler.filter, TexFilter::nearest);
  EXPECT_EQ(in[0].sampler.wrap, TexWrap::mirror);
  EXPECT_TRUE(in[0].sampler.vflip);
  EXPECT_EQ(in[1].sampler.filter, TexFilter::linear);  // the extension's default: linear, repeat
  EXPECT_EQ(in[1].sampler.wrap, TexWrap::repeat);
  EXPECT_EQ(in[2].kind, InputKind::cubemap);
  EXPECT_EQ(fs::path(in[2].src).filename(), "sky_{}.jpg");
  EXPECT_EQ(in[3].kind, InputKind::music);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(VsCode, MipmapAndMixedFiltersMapWithAWarning) {
  Dir d;
  d.put("t.png", "x");
  d.put("m.glsl", "#iChannel0 \"file://t.png\"\n#iChannel0::MinFilter \"NearestMipMapNearest\"\n"
                  "#iChannel1 \"file://t.png\"\n#iChannel1::MinFilter \"LinearMipMapLinear\"\n" + kImage);
  const ShaderProject p = d.load("m.glsl");
  EXPECT_EQ(p.passes[0].inputs[0].sampler.filter, TexFilter::mipmap);
  EXPECT_EQ(p.passes[0].inputs[1].sampler.filter, TexFilter::mipmap);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("m.glsl:2"), std::string::npos) << p.warnings[0];
}

TEST(VsCode, SelfInTheMainFileMakesItABufferShownByADisplayPass) {
  Dir d;
  d.put("m.glsl", "#iChannel1 \"self\"\n" + kImage);
  const ShaderProject p = d.load("m.glsl");
  ASSERT_EQ(p.passes.size(), 2u);
  EXPECT_EQ(p.passes[0].kind, PassKind::buffer);
  EXPECT_EQ(p.passes[0].inputs[1].buffer, 0);
  EXPECT_EQ(p.passes[1].kind, PassKind::image);
  EXPECT_EQ(p.passes[1].inputs[0].buffer, 0);
}

TEST(VsCode, KeyboardTakesAFreeChannelAndDefinesTheHelpers) {
  Dir d;
  d.put("b.glsl", kImage);
  d.put("m.glsl", "#iChannel0 \"file://b.glsl\"\n#iKeyboard\n"
                  "void mainImage(out vec4 c, in vec2 f) { c = vec4(isKeyDown(Key_A) ? 1.0 : 0.0); }\n");
  const ShaderProject p = d.load("m.glsl");
  const ProjectPass& img = p.passes.back();
  EXPECT_EQ(img.inputs[1].kind, InputKind::keyboard);
  EXPECT_EQ(img.code.substr(0, img.code.find("void")), "\n#define iKeyboard iChannel1\n");
  for (const char* f : {"isKeyDown", "isKeyPressed", "isKeyToggled", "isKeyReleased", "Key_A = 65", "Key_UpArrow = 38"})
    EXPECT_NE(p.common.find(f), std::string::npos) << f;
  EXPECT_EQ(p.passes[0].inputs[0].kind, InputKind::none);  // only the pass that asks
}

TEST(VsCode, UniformsBecomeAnnotatedUniforms) {
  EXPECT_EQ(vscode_uniform_line(" float k = 1.0 in { 0.0, 5.0 } step 0.2", "x", 1),
            "uniform float k = 1.0; // range(0.0, 5.0)");
  EXPECT_EQ(vscode_uniform_line(" color3 tint = color3(1.0, 0.5, 0.25)", "x", 1), "uniform vec3 tint = vec3(1.0, 0.5, 0.25); // color");
  EXPECT_EQ(vscode_uniform_line(" vec2 at = vec2(1.0)", "x", 1), "uniform vec2 at = vec2(1.0);");
  EXPECT_EQ(vscode_uniform_line(" int n in { 2, 8 }", "x", 1), "uniform int n = 2; // range(2, 8)");
  const std::vector<SceneParam> ps = parse_scene_params(vscode_uniform_line(" vec4 v=vec4(0.5) in {0, 1}", "x", 1));
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_EQ(ps[0].name, "v");
  EXPECT_FLOAT_EQ(ps[0].hi, 1.0f);
  EXPECT_FLOAT_EQ(ps[0].initial[3], 0.5f);
  for (const char* bad : {" ivec2 p = ivec2(1)", " float k", " float k = vec3(1.0, 2.0)", " vec2 r = vec2(0) in { vec2(0, 1), vec2(1) }",
                          " float k = 1.0 in { 2.0, 1.0 }", " mat3 m = 1.0"}) {
    try {
      vscode_uniform_line(bad, "m.glsl", 7);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.info().line, 7) << bad;
      EXPECT_EQ(e.info().key, "#iUniform") << bad;
    }
  }
}

TEST(VsCode, BadInputNamesItsFileLineAndDirective) {
  Dir d;
  d.put("wrap.glsl", "\n#iChannel0 \"self\"\n#iChannel0::WrapMode \"Bounce\"\n" + kImage);
  EXPECT_NE(d.error("wrap.glsl").find("wrap.glsl:3: #iChannel0::WrapMode: "), std::string::npos) << d.error("wrap.glsl");
  d.put("setting.glsl", "#iChannel1::Filter \"Linear\"\n" + kImage);
  EXPECT_NE(d.error("setting.glsl").find("setting.glsl:1: #iChannel1::Filter"), std::string::npos);
  d.put("five.glsl", "\n\n#iChannel5 \"self\"\n" + kImage);
  EXPECT_NE(d.error("five.glsl").find("five.glsl:3: #iChannel5"), std::string::npos);
  d.put("url.glsl", "#iChannel0 \"https://example.com/a.png\"\n" + kImage);
  EXPECT_NE(d.error("url.glsl").find("url.glsl:1: #iChannel0: 'https://example.com/a.png' is not fetched"), std::string::npos)
      << d.error("url.glsl");
  d.put("gone.glsl", "\n#iChannel2 \"file://nothere.png\"\n" + kImage);
  EXPECT_NE(d.error("gone.glsl").find("gone.glsl:2: #iChannel2: "), std::string::npos) << d.error("gone.glsl");
  EXPECT_NE(d.error("gone.glsl").find("nothere.png' not found"), std::string::npos)
      << d.error("gone.glsl");
  d.put("fly.glsl", "#iFirstPersonControls\n" + kImage);
  EXPECT_NE(d.error("fly.glsl").find("fly.glsl:1: #iFirstPersonControls"), std::string::npos);
  d.put("main.glsl", "#iKeyboard\nvoid main() { }\nvoid mainImage(out vec4 c, in vec2 f) { }\n");
  EXPECT_NE(d.error("main.glsl").find("main.glsl:2: void main() and mainImage() both defined"), std::string::npos) << d.error("main.glsl");
  d.put("cube.glsl", "#iChannel0 \"file://b.glsl\"\n#iChannel0::Type \"CubeMap\"\n" + kImage);
  d.put("b.glsl", kImage);
  EXPECT_NE(d.error("cube.glsl").find("cube.glsl:2: #iChannel0::Type"), std::string::npos) << d.error("cube.glsl");
  // A buffer's own bad line is named in the buffer's file.
  d.put("outer.glsl", "#iChannel0 \"file://inner.glsl\"\n" + kImage);
  d.put("inner.glsl", "\n\n\n#iChannel0 \"file://x.png\"\n#iChannel0 \"file://y.png\"\n" + kImage);
  EXPECT_NE(d.error("outer.glsl").find("inner.glsl:5: #iChannel0: the channel is already bound at line 4"), std::string::npos) << d.error("outer.glsl");
}

TEST(VsCode, PathsOutsideTheRootsAreRefused) {
  Dir d;
  d.put("in/m.glsl", "\n#iChannel0 \"file://../secret.glsl\"\n" + kImage);
  d.put("secret.glsl", kImage);
  std::ifstream f(d.path / "in/m.glsl");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  try {
    load_vscode(text, d.path / "in/m.glsl", {d.path / "in"});
    ADD_FAILURE() << "accepted a path outside the roots";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().line, 2);
    EXPECT_EQ(e.info().key, "#iChannel0");
    EXPECT_NE(e.info().what.find("is outside the directories includes may read"), std::string::npos) << e.info().what;
  }
}

TEST(VsCode, MoreThanFourBuffersIsAnError) {
  Dir d;
  std::string main;
  for (int i = 0; i < 4; ++i) {
    d.put("b" + std::to_string(i) + ".glsl", i < 3 ? "#iChannel0 \"file://b" + std::to_string(i + 1) + ".glsl\"\n" + kImage : kImage);
  }
  d.put("ok.glsl", "#iChannel0 \"file://b0.glsl\"\n" + kImage);
  EXPECT_EQ(d.load("ok.glsl").passes.size(), 5u);
  d.put("b3.glsl", "#iChannel0 \"file://b4.glsl\"\n" + kImage);
  d.put("b4.glsl", kImage);
  EXPECT_NE(d.error("ok.glsl").find("b4.glsl' would be a 5th buffer"), std::string::npos) << d.error("ok.glsl");
}

}  // namespace
}  // namespace ms
