// Per-scene specialization (shader/specialize.h, docs/specialization.md) on
// the real library and scenes: the defines, what the assembled source still
// contains once preprocessed (glslangValidator -E, skipped without it), that
// every variant compiles, and the program cache key.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>

#include "core/error.h"
#include "render/aov.h"
#include "scene/features.h"
#include "scene/load.h"
#include "shader/assemble.h"
#include "shader/specialize.h"
#include "test_shader_util.h"

namespace ms {
namespace {

namespace fs = std::filesystem;

fs::path source(const std::string& rel) { return fs::path(MARCH_SOURCE_DIR) / rel; }
fs::path data(const std::string& rel) { return fs::path(MARCH_TEST_DATA) / "specialize" / rel; }

AssembleOptions options(Specialization mode, std::vector<std::pair<std::string, std::string>> defines = {}) {
  AssembleOptions o{source("sdf_shaders"), std::move(defines)};
  o.specialize = mode;
  return o;
}

// Every scene the tests measure: the shipped ones and tests/data/specialize/.
std::vector<fs::path> all_scenes() {
  std::vector<fs::path> out;
  for (const fs::path& dir : {source("scenes"), data("")})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".toml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

// The source as the compiler sees it after its preprocessor: only the
// active #if branches, macros expanded.
std::string preprocessed(const std::string& text, const std::string& tag) {
  const test::TempDir dir;
  const fs::path f = dir / (tag + ".frag");
  { std::ofstream(f, std::ios::binary) << text; }
  std::string out;
  if (FILE* p = ::popen(("glslangValidator -E -S frag '" + f.string() + "' 2>/dev/null").c_str(), "r")) {
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    ::pclose(p);
  }
  return out;
}

// The body of the function `signature` ("vec3 renderSample(") in preprocessed
// text, braces included; empty when it is not defined there.
std::string body_of(const std::string& text, const std::string& signature) {
  size_t at = 0;
  while ((at = text.find(signature, at)) != std::string::npos) {
    const size_t open = text.find_first_of("{;", at);
    if (open == std::string::npos) return {};
    if (text[open] == ';') {  // a prototype
      at = open;
      continue;
    }
    int depth = 0;
    for (size_t i = open; i < text.size(); ++i) {
      depth += text[i] == '{' ? 1 : text[i] == '}' ? -1 : 0;
      if (depth == 0) return text.substr(open, i - open + 1);
    }
    return {};
  }
  return {};
}

bool has_loop(const std::string& code) {
  for (const char* kw : {"for (", "for(", "while (", "while("})
    if (code.find(kw) != std::string::npos) return true;
  return false;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// options() with a graph scene's shape prepared, as the pipeline prepares it.
AssembleOptions options_for(const Scene& s, Specialization mode,
                            std::vector<std::pair<std::string, std::string>> defines = {}) {
  AssembleOptions o = options(mode, std::move(defines));
  prepare_graph_shape(s, o);
  return o;
}

std::string active(const fs::path& scene, Specialization mode) {
  const Scene s = load_scene(scene);
  return preprocessed(assemble_scene(s, options_for(s, mode)).text, scene.stem().string());
}

TEST(Specialize, GenericAddsNothing) {
  const Scene s = load_scene(data("matte.toml"));
  const Specialized g = specialize(s, scene_features(s, options(Specialization::folded)), Specialization::generic);
  EXPECT_TRUE(g.defines.empty());
  EXPECT_TRUE(g.constants.empty());
  EXPECT_EQ(g.quality.bounces, s.quality.bounces);
  EXPECT_TRUE(g.quality.reflections);
  // And the generic root is exactly the pre-specialization one: no SPECIALIZED define.
  EXPECT_EQ(assemble_scene(s, options(Specialization::generic)).text.find("#define SPECIALIZED 1"),
            std::string::npos);
}

TEST(Specialize, FoldedRenderShaderOfAMatteOneLightScene) {
  const Scene s = load_scene(data("matte.toml"));
  const FeatureSet f = scene_features(s, options(Specialization::folded));
  EXPECT_FALSE(f.reflective);
  EXPECT_EQ(f.library, (std::vector<std::string>{"opUnion", "sdPlane", "sdRoundBox", "sdSphere"}));
  const std::string text = assemble_scene(s, options(Specialization::folded)).text;
  for (const char* l : {"#define SPECIALIZED 1", "#define MAX_BOUNCES 0", "#define ENABLE_REFLECTIONS 0",
                        "#define ENABLE_SHADOWS 1", "#define USE_CHECKER 1", "#define MATERIAL_IS_CHECKER(id) ((id) == 0)",
                        "#define NUM_POINT_LIGHTS 1", "#define NUM_DIRECTIONAL_LIGHTS 0", "#define LIGHT_UNIFORMS 0",
                        "#define MATERIAL_UNIFORMS 0", "#define SKY_UNIFORMS 0", "#define MS_LIBRARY_SUBSET 1",
                        "#define USE_SDROUNDBOX 1", "const float kLightSize[1] = float[](0.4);",
                        "  m.ka = 1.0;"})
    EXPECT_TRUE(has_line(text, l)) << l;
  EXPECT_EQ(text.find("#define USE_SDTORUS"), std::string::npos);
  // The folded values come right after the prelude, before any library code that reads them.
  EXPECT_LT(text.find("Material sceneMaterial(int id)"), text.find("Surface getSurface("));
}

TEST(Specialize, TheViewersShaderKeepsWhatThePanelDrags) {
  const Scene s = load_scene(data("matte.toml"));
  const std::string text = assemble_scene(s, options(Specialization::uniforms)).text;
  for (const char* l : {"#define SPECIALIZED 1", "#define MAX_BOUNCES 0", "#define LIGHT_UNIFORMS 1",
                        "#define MATERIAL_UNIFORMS 1", "#define SKY_UNIFORMS 1", "#define NUM_DIRECTIONAL_LIGHTS 0"})
    EXPECT_TRUE(has_line(text, l)) << l;
  EXPECT_EQ(text.find("kLightPos"), std::string::npos);
  EXPECT_EQ(text.find("Material sceneMaterial(int id) {\n  Material m;"), std::string::npos);
}

TEST(Specialize, AnimatedTablesStayUniformsAndAKeyedMirrorKeepsReflections) {
  const Scene s = load_scene(data("animated.toml"));
  const std::string text = assemble_scene(s, options(Specialization::folded)).text;
  for (const char* l : {"#define ENABLE_REFLECTIONS 1", "#define MAX_BOUNCES 1", "#define LIGHT_UNIFORMS 1",
                        "#define MATERIAL_UNIFORMS 1", "#define SKY_UNIFORMS 0",
                        "#define LIGHT_IS_POINT(i) ((i) == 0)"})
    EXPECT_TRUE(has_line(text, l)) << l;
}

TEST(Specialize, GlslLightIsWhatTheUniformsHold) {
  Light d;
  d.kind = LightKind::directional;
  d.direction = glm::vec3(0.0f, -2.0f, 0.0f);
  d.size = 2.0f;  // degrees, diameter
  d.intensity = 3.0f;
  d.color = glm::vec3(0.5f, 1.0f, 0.25f);
  const GlslLight g = glsl_light(d);
  EXPECT_EQ(g.pos, glm::vec4(0.0f, -1.0f, 0.0f, 0.0f));
  EXPECT_FLOAT_EQ(g.size, 2.0f * 3.14159265358979f / 180.0f * 0.5f);
  EXPECT_EQ(g.color, glm::vec3(1.5f, 3.0f, 0.75f));
  Light p;
  p.position = glm::vec3(1.0f, 2.0f, 3.0f);
  p.size = 0.3f;
  EXPECT_EQ(glsl_light(p).pos, glm::vec4(1.0f, 2.0f, 3.0f, 1.0f));
  EXPECT_FLOAT_EQ(glsl_light(p).size, 0.3f);
}

TEST(SpecializeSource, NoReflectionLoopWithoutAMirror) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  const std::string spec = active(data("matte.toml"), Specialization::folded);
  const std::string render = body_of(spec, "vec3 renderSample(");
  ASSERT_FALSE(render.empty()) << spec.substr(0, 2000);
  EXPECT_FALSE(has_loop(render)) << render;
  EXPECT_EQ(count(render, "traceSegment("), 1u);
  EXPECT_EQ(count(spec, "reflect("), 0u) << "no reflected ray is ever made";
  // The check can fail: the generic shader of the same scene loops over segments.
  const std::string gen = active(data("matte.toml"), Specialization::generic);
  EXPECT_TRUE(has_loop(body_of(gen, "vec3 renderSample("))) << body_of(gen, "vec3 renderSample(");
  // A scene with a mirror keeps its loop when specialized.
  EXPECT_TRUE(has_loop(body_of(active(source("scenes/seed.toml"), Specialization::folded), "vec3 renderSample(")));
}

TEST(SpecializeSource, OneLightHasNoLightLoopAndNoOtherKind) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  for (const fs::path& scene : {source("scenes/seed.toml"), data("matte.toml")}) {
    for (Specialization mode : {Specialization::folded, Specialization::uniforms}) {
      const std::string spec = active(scene, mode);
      const std::string shade = body_of(spec, "vec3 shadeBlinnPhong(");
      ASSERT_FALSE(shade.empty()) << scene;
      EXPECT_FALSE(has_loop(shade)) << scene << " " << specialization_name(mode) << shade;
      EXPECT_EQ(count(shade, "sceneLight("), 1u) << shade;
      EXPECT_TRUE(body_of(spec, "void directionalLightAt(").empty()) << "a point light only: no directional code";
      EXPECT_FALSE(has_loop(body_of(spec, "vec3 sceneLight("))) << body_of(spec, "vec3 sceneLight(");
    }
    const std::string gen = active(scene, Specialization::generic);
    EXPECT_TRUE(has_loop(body_of(gen, "vec3 shadeBlinnPhong("))) << "the generic shader loops";
    EXPECT_FALSE(body_of(gen, "void directionalLightAt(").empty());
  }
  // Directional lights only: no point-light code.
  const std::string suns = active(data("suns.toml"), Specialization::folded);
  EXPECT_TRUE(body_of(suns, "void pointLightAt(").empty());
  EXPECT_FALSE(body_of(suns, "void directionalLightAt(").empty());
}

TEST(SpecializeSource, CheckerAndLibraryCodeOnlyWhenUsed) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  const std::string matte = active(data("matte.toml"), Specialization::folded);
  const std::string suns = active(data("suns.toml"), Specialization::folded);
  EXPECT_FALSE(body_of(matte, "float checkerFiltered(").empty());
  EXPECT_TRUE(body_of(suns, "float checkerFiltered(").empty()) << "no material has a checker";
  EXPECT_EQ(body_of(suns, "Surface getSurface(").find("projectDominant"), std::string::npos);
  EXPECT_FALSE(body_of(matte, "float sdRoundBox(").empty());
  EXPECT_TRUE(body_of(matte, "float sdTorus(").empty());
  EXPECT_TRUE(body_of(matte, "float opSmoothUnion(").empty());
  // suns calls opSmoothSubtraction, which is built on opSmoothUnion.
  EXPECT_FALSE(body_of(suns, "float opSmoothSubtraction(").empty());
  EXPECT_FALSE(body_of(suns, "float opSmoothUnion(").empty());
  EXPECT_TRUE(body_of(suns, "float sdBox(").empty());
  // The generic shader keeps all of it.
  const std::string gen = active(data("suns.toml"), Specialization::generic);
  for (const char* f : {"float checkerFiltered(", "float sdTorus(", "float sdBox(", "domRepeatCell("})
    EXPECT_FALSE(body_of(gen, f).empty()) << f;
  EXPECT_LT(matte.size(), active(data("matte.toml"), Specialization::generic).size());
}

// Every guarded library function (sdf_shaders/), with the library names
// its own code calls.
std::map<std::string, std::vector<std::string>> library_functions() {
  const std::regex guard(R"(^#if !defined\(MS_LIBRARY_SUBSET\) \|\| defined\(USE_[A-Z0-9]+\)\s*$)");
  const std::regex def(R"(^\s*(?:float|vec2|vec3|vec4)\s+(\w+)\s*\()");
  std::map<std::string, std::vector<std::string>> out;
  for (const auto& e : fs::directory_iterator(source("sdf_shaders"))) {
    std::ifstream in(e.path());
    std::string line, name, block;
    bool inside = false;
    std::smatch m;
    while (std::getline(in, line)) {
      if (std::regex_match(line, guard)) {
        inside = true;
        name.clear();
        block.clear();
      } else if (inside && line.rfind("#endif", 0) == 0) {
        inside = false;
        std::vector<std::string> calls = referenced_library_names(block);
        std::erase(calls, name);
        if (!name.empty()) out[name] = calls;
      } else if (inside) {
        if (name.empty() && std::regex_search(line, m, def)) name = m[1];
        block += line + "\n";
      }
    }
  }
  return out;
}

// Specialization keeps exactly the library code a scene's map uses: the
// functions its map (and what it includes) names and what those call, no
// other, for every shipped and test scene.
TEST(SpecializeSource, EachSceneKeepsOnlyTheLibraryFunctionsItUses) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  const auto lib = library_functions();
  ASSERT_GT(lib.size(), 80u);
  for (const fs::path& scene : all_scenes()) {
    const Scene s = load_scene(scene);
    std::set<std::string> want;
    std::vector<std::string> todo = scene_features(s, options_for(s, Specialization::folded)).library;
    while (!todo.empty()) {
      const std::string n = todo.back();
      todo.pop_back();
      const auto it = lib.find(n);
      if (it == lib.end() || !want.insert(n).second) continue;
      todo.insert(todo.end(), it->second.begin(), it->second.end());
    }
    const std::string spec = active(scene, Specialization::folded);
    ASSERT_FALSE(spec.empty()) << scene;
    std::set<std::string> defined_names;  // every function the compiler sees defined
    const std::regex def(R"(\b(?:float|vec2|vec3|vec4)\s+(\w+)\s*\()");
    for (auto it = std::sregex_iterator(spec.begin(), spec.end(), def); it != std::sregex_iterator(); ++it)
      defined_names.insert((*it)[1]);
    for (const auto& [name, calls] : lib) {
      const bool defined = defined_names.count(name) > 0;
      EXPECT_EQ(defined, want.count(name) > 0) << scene.filename() << ": " << name
                                               << (defined ? " is compiled in but not used" : " is used but missing");
    }
  }
}

TEST(SpecializeSource, EveryVariantOfEverySceneCompiles) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  using Defines = std::vector<std::pair<std::string, std::string>>;
  // Each mode as it is used: render/bench (folded, and its AOV counting
  // pass), the viewer (uniforms, and a debug view), --no-specialize.
  const std::vector<std::pair<Specialization, Defines>> variants = {
      {Specialization::generic, {}},
      {Specialization::folded, {}},
      {Specialization::folded, aov_defines()},
      {Specialization::uniforms, {}},
      {Specialization::uniforms, {{"DEBUG_VIEW", "5"}}},
  };
  for (const fs::path& scene : all_scenes()) {
    const Scene s = load_scene(scene);
    for (const auto& [mode, extra] : variants) {
      const ShaderSource src = assemble_scene(s, options_for(s, mode, extra));
      const test::GlslangResult r = test::run_glslang(src.text, "spec");
      EXPECT_EQ(r.status, 0) << scene << " " << specialization_name(mode) << " with " << extra.size()
                             << " extra defines:\n" << r.output.substr(0, 2000);
    }
  }
}

// The viewer's cache: a program is rebuilt exactly when the feature set
// changes. In the viewer's mode every draggable value is a uniform, so the
// assembled source (and its key) moves with the features alone.
TEST(SpecializeCache, KeyChangesExactlyWhenTheFeatureSetChanges) {
  const Scene base = load_scene(data("matte.toml"));
  struct Variant {
    const char* what;
    std::function<void(Scene&)> edit;
  };
  const std::vector<Variant> variants = {
      {"the file as is", [](Scene&) {}},
      {"a light's colour and place", [](Scene& s) { s.lights[0].color = glm::vec3(0.2f); s.lights[0].position.x = 9.0f; }},
      {"a material's colour", [](Scene& s) { s.materials[1].color = glm::vec3(0.0f, 1.0f, 0.0f); }},
      {"the sky and the camera", [](Scene& s) { s.sky.zenith = glm::vec3(1.0f); s.camera.fov_deg = 70.0f; }},
      {"a mirror", [](Scene& s) { s.materials[1].reflectivity = 0.1f; }},
      {"a brighter mirror", [](Scene& s) { s.materials[1].reflectivity = 0.7f; s.materials[1].specular = 0.1f; }},
      {"a mirror, 3 bounces", [](Scene& s) { s.materials[1].reflectivity = 0.1f; s.quality.bounces = 3; }},
      {"no shadows", [](Scene& s) { s.quality.shadows = false; }},
      {"no AO", [](Scene& s) { s.quality.ao = false; }},
      {"no checker", [](Scene& s) { s.materials[0].pattern = Pattern::none; }},
      {"a directional light", [](Scene& s) { s.lights[0].kind = LightKind::directional; }},
      {"a second light", [](Scene& s) { s.lights.push_back(s.lights[0]); }},
      {"a map with a torus", [](Scene& s) { s.map_file = data("torus.glsl"); }},
  };
  const AssembleOptions opts = options(Specialization::uniforms);
  const std::string vs = fullscreen_vertex_source();
  std::vector<FeatureSet> features;
  std::vector<std::uint64_t> keys;
  for (const Variant& v : variants) {
    Scene s = base;
    v.edit(s);
    features.push_back(scene_features(s, opts));
    keys.push_back(program_key(vs, assemble_scene(s, opts).text));
  }
  int same = 0;
  for (size_t i = 0; i < variants.size(); ++i)
    for (size_t j = i + 1; j < variants.size(); ++j) {
      const bool same_features = features[i] == features[j];
      same += same_features;
      EXPECT_EQ(same_features, keys[i] == keys[j]) << "'" << variants[i].what << "' vs '" << variants[j].what << "'";
    }
  EXPECT_GE(same, 5) << "the value-only edits must share a feature set";

  // Folded (render), the values are in the source: they change the key too.
  Scene red = base;
  red.materials[1].color = glm::vec3(1.0f, 0.0f, 0.0f);
  const AssembleOptions folded = options(Specialization::folded);
  EXPECT_NE(program_key(vs, assemble_scene(base, folded).text), program_key(vs, assemble_scene(red, folded).text));
  // The key covers the vertex source and is stable.
  EXPECT_NE(program_key("a", "bc"), program_key("ab", "c"));
  EXPECT_EQ(program_key(vs, "x"), program_key(vs, "x"));
}

}  // namespace
}  // namespace ms
