// assemble_scene / assemble_post / fullscreen_vertex_source / glsl_float and
// the Shadertoy wrapper, against stub libraries in tests/data/shader/.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <regex>

#include "core/error.h"
#include "shader/assemble.h"
#include "preprocess/log_map.h"
#include "importers/shadertoy.h"
#include "test_shader_util.h"

namespace ms {
namespace {

namespace fs = std::filesystem;
using test::shader_data;

AssembleOptions fake_lib() { return {shader_data("fake_lib")}; }

Scene test_scene() {
  Scene s;
  s.file = shader_data("scene/test.toml");
  s.map_file = shader_data("scene/map.glsl");
  s.name = "test";
  Material floor;
  floor.name = "floor";
  Material ball;
  ball.name = "Ball_2";
  s.materials = {floor, ball};
  s.lights.resize(3);
  s.quality.max_steps = 300;
  s.quality.max_distance = 250.0f;
  s.quality.hit_tolerance = 0.75f;
  s.quality.hit_epsilon = 1e-5f;
  s.quality.lipschitz = 1.5f;
  s.quality.shadow_steps = 32;
  s.quality.ao_taps = 0;
  s.quality.bounces = 2;
  s.quality.shadows = true;
  s.quality.ao = false;
  s.quality.reflections = false;
  s.quality.checker_filter = true;
  return s;
}

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST(ShaderFloat, GlslLiteralsRoundTrip) {
  const std::regex literal(R"(^\(?-?(\d+\.\d*|\.\d+|\d+(\.\d*)?[eE][+-]?\d+)\)?$)");
  const float values[] = {100.0f, 0.5f, 1e-4f, 1e-5f, 0.1f, 1.0f / 3.0f, 255.0f, 1e20f, 3.4028235e38f,
                          1.4e-45f, 0.0f, -2.5f, 16777217.0f, 123456.789f};
  for (float v : values) {
    const std::string s = glsl_float(v);
    EXPECT_TRUE(std::regex_match(s, literal)) << s;
    std::string digits = s;
    if (digits.front() == '(') digits = digits.substr(1, digits.size() - 2);
    float back = 0.0f;
    auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), back);
    EXPECT_EQ(ec, std::errc()) << s;
    EXPECT_EQ(p, digits.data() + digits.size()) << s;
    EXPECT_EQ(back, v) << s;
  }
  EXPECT_EQ(glsl_float(100.0f), "100.0");
  EXPECT_EQ(glsl_float(0.5f), "0.5");
  EXPECT_EQ(glsl_float(-2.5f), "(-2.5)");
  EXPECT_THROW(glsl_float(std::numeric_limits<float>::infinity()), Error);
  EXPECT_THROW(glsl_float(std::nanf("")), Error);
}

TEST(ShaderFloat, GlslangParsesTheLiteralsAsFloats) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  // `const float` from an int would also compile, so check float-ness via
  // overloads that differ only in the parameter type and return distinct types.
  std::string src = "#version 450 core\nbool isf(float x) { return true; }\nint isf(int x) { return 0; }\n"
                    "layout(location = 0) out vec4 o;\nvoid main() {\n  bool b = true;\n";
  for (float v : {100.0f, 1e-4f, 1e20f, 1.4e-45f, -2.5f, 0.0f})
    src += "  b = b && isf(" + glsl_float(v) + ");\n";
  src += "  o = vec4(b ? 1.0 : 0.0);\n}\n";
  test::GlslangResult r = test::run_glslang(src, "floats");
  EXPECT_EQ(r.status, 0) << r.output << src;
}

TEST(ShaderAssemble, SceneDefinesFromTheSceneStruct) {
  ShaderSource s = assemble_scene(test_scene(), fake_lib());
  EXPECT_EQ(s.text.rfind("#version 450 core\n", 0), 0u);
  for (const char* l : {"#define NUM_LIGHTS 3", "#define NUM_MATERIALS 2", "#define MAT_FLOOR 0",
                        "#define MAT_BALL_2 1", "#define MAX_STEPS 300", "#define MAX_DIST 250.0",
                        "#define HIT_TOLERANCE 0.75", "#define HIT_EPSILON 1e-05", "#define LIPSCHITZ 1.5",
                        "#define SHADOW_STEPS 32", "#define AO_TAPS 0", "#define MAX_BOUNCES 2",
                        "#define ENABLE_SHADOWS 1", "#define ENABLE_AO 0", "#define ENABLE_REFLECTIONS 0",
                        "#define ENABLE_CHECKER_FILTER 1"})
    EXPECT_TRUE(has_line(s.text, l)) << l;
  EXPECT_EQ(s.files[0], "test.frag (generated)");
  // prelude, primitives (once, though map.glsl includes it too), operators, noise, map, main.
  ASSERT_EQ(s.files.size(), 7u);
  EXPECT_EQ(s.files[5], display_path(shader_data("scene/map.glsl")));
  EXPECT_EQ(s.dependencies.size(), 6u);
  // The defines come before any library code.
  EXPECT_LT(s.text.find("#define ENABLE_CHECKER_FILTER"), s.text.find("#line 100001 1"));
}

TEST(ShaderAssemble, SceneCompilesWithGlslang) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  ShaderSource s = assemble_scene(test_scene(), fake_lib());
  test::GlslangResult r = test::run_glslang(s.text, "scene");
  EXPECT_EQ(r.status, 0) << format_diagnostics(parse_info_log(r.output, s));
}

TEST(ShaderAssemble, SceneErrorsPointAtTheScene) {
  Scene s = test_scene();
  s.map_file = shader_data("scene/nope.glsl");
  try {
    assemble_scene(s, fake_lib());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().key, "scene.map");
    EXPECT_EQ(e.info().file, display_path(shader_data("scene/test.toml")));
  }
  s = test_scene();
  s.materials[1].name = "has space";
  EXPECT_THROW(assemble_scene(s, fake_lib()), Error);
  s.materials.clear();
  EXPECT_THROW(assemble_scene(s, fake_lib()), Error);
}

TEST(ShaderAssemble, PostPassDefines) {
  ShaderSource s = assemble_post(Tonemap::reinhard, true, fake_lib());
  EXPECT_TRUE(has_line(s.text, "#define TONEMAP 1"));
  EXPECT_TRUE(has_line(s.text, "#define ENCODE_SRGB 1"));
  EXPECT_NE(s.text.find("void main() { outColor = vec4(float(TONEMAP)"), std::string::npos);
  ShaderSource n = assemble_post(Tonemap::none, false, fake_lib());
  EXPECT_TRUE(has_line(n.text, "#define TONEMAP 0"));
  EXPECT_TRUE(has_line(n.text, "#define ENCODE_SRGB 0"));
  EXPECT_TRUE(has_line(assemble_post(Tonemap::aces, true, fake_lib()).text, "#define TONEMAP 2"));
}

TEST(ShaderAssemble, FullscreenVertexShaderCompiles) {
  const std::string v = fullscreen_vertex_source();
  EXPECT_NE(v.find("gl_VertexID"), std::string::npos);
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  const test::TempDir dir;
  const fs::path f = dir / "fullscreen.vert";
  { std::ofstream(f) << v; }
  const int rc = std::system(("glslangValidator '" + f.string() + "' >/dev/null 2>&1").c_str());
  EXPECT_EQ(rc, 0);
}

TEST(ShaderShadertoy, Detection) {
  EXPECT_TRUE(looks_like_shadertoy("void mainImage( out vec4 c, in vec2 p ) { c = vec4(1.0); }"));
  EXPECT_FALSE(looks_like_shadertoy("void mainImage(out vec4 c, in vec2 p) {}\nvoid main() {}"));
  EXPECT_TRUE(looks_like_shadertoy("// void main() {}\nvoid mainImage(out vec4 c, in vec2 p) {}\n/* void main(){} */"));
  EXPECT_FALSE(looks_like_shadertoy("float mainImageScale; void main(){}"));
  EXPECT_FALSE(looks_like_shadertoy("vec2 map(vec3 p) { return vec2(0.0); }"));
}

TEST(ShaderShadertoy, WrapperDeclaresUniformsAndCompiles) {
  ShaderSource s = assemble_shadertoy(shader_data("shadertoy/ok.glsl"), fake_lib());
  EXPECT_EQ(s.text.rfind("#version 450 core\n", 0), 0u);
  for (const char* u : {"uniform vec3      iResolution;", "uniform float     iTime;", "uniform int       iFrame;",
                        "uniform vec4      iMouse;", "uniform vec4      iDate;", "uniform float     iChannelTime[4];",
                        "uniform vec3      iChannelResolution[4];", "uniform sampler2D iChannel3;",
                        "uniform vec2      uJitter;"})
    EXPECT_NE(s.text.find(u), std::string::npos) << u;
  EXPECT_NE(s.text.find("mainImage(c, floor(gl_FragCoord.xy) + uPixelOffset + uJitter);"), std::string::npos);
  // ok.glsl includes lib/palette.glsl (next to it) and primitives.glsl (shader dir).
  EXPECT_EQ(s.dependencies.size(), 3u);
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  test::GlslangResult r = test::run_glslang(s.text, "toy");
  EXPECT_EQ(r.status, 0) << format_diagnostics(parse_info_log(r.output, s));
}

TEST(ShaderShadertoy, ErrorsMapToTheUsersFile) {
  const fs::path bad = shader_data("shadertoy/bad.glsl");
  ShaderSource s = assemble_shadertoy(bad, fake_lib());
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  test::GlslangResult r = test::run_glslang(s.text, "toybad");
  auto d = parse_info_log(r.output, s);
  ASSERT_FALSE(d.empty());
  const ShaderDiagnostic* first = nullptr;
  for (const auto& x : d)
    if (!x.file.empty() && !first) first = &x;
  ASSERT_NE(first, nullptr) << r.output;
  EXPECT_EQ(first->file, display_path(bad));
  EXPECT_EQ(first->line, test::line_containing(test::read_file(bad), "undefined_MARK_ST"));
}

TEST(ShaderShadertoy, RejectsMainAndMissingFiles) {
  try {
    assemble_shadertoy(shader_data("shadertoy/has_main.glsl"), fake_lib());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().line, 3);
    EXPECT_NE(e.info().what.find("main()"), std::string::npos);
  }
  EXPECT_THROW(assemble_shadertoy(shader_data("shadertoy/none.glsl"), fake_lib()), Error);
}

}  // namespace
}  // namespace ms

namespace ms {
namespace {

TEST(ShaderAssembleDefines, ExtraDefinesFollowTheScenesAndClashesAreErrors) {
  Scene scene;
  scene.file = std::filesystem::path(MARCH_TEST_DATA) / "shader/scene/scene.toml";
  scene.map_file = std::filesystem::path(MARCH_TEST_DATA) / "shader/scene/map.glsl";
  scene.materials.push_back(Material{});
  scene.materials[0].name = "a";
  AssembleOptions opts{std::filesystem::path(MARCH_TEST_DATA) / "shader/fake_lib", {{"DEBUG_VIEW", "2"}}};
  const ShaderSource src = assemble_scene(scene, opts);
  const size_t extra = src.text.find("#define DEBUG_VIEW 2\n");
  ASSERT_NE(extra, std::string::npos);
  EXPECT_LT(src.text.find("#define ENABLE_CHECKER_FILTER"), extra);
  opts.defines = {{"MAX_STEPS", "10"}};
  EXPECT_THROW(assemble_scene(scene, opts), Error);
}

}  // namespace
}  // namespace ms
