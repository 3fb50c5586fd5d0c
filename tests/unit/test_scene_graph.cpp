// The scene graph: its JSON reader, its errors (file:line: pointer), its
// vocabulary checked against the library's GLSL, transforms, boxes,
// Lipschitz bounds and what a scene takes from them.
#include <pthread.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <regex>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/error.h"
#include "files.h"
#include "graph_of.h"
#include "io/json_doc.h"
#include "scene/graph_build.h"
#include "scene/graph_scene.h"
#include "scene/graph_vocab.h"
#include "scene/load.h"
#include "scene/quality.h"
#include "shader/assemble.h"

namespace fs = std::filesystem;
using ms::test::TempDir;
using ms::test::write_file;

namespace {

using ms::test::graph_of;
using ms::test::graph_error;

TEST(JsonDoc, ValuesKnowTheirLineAndPointer) {
  const ms::JsonDoc d = ms::parse_json_doc("{\n\"a/b\": [1,\n {\"x~\": \"s\\u00e9\"}]\n}", "t.json");
  const int arr = d.member(0, "a/b");
  ASSERT_NE(arr, -1);
  const int obj = d.at(d.at(arr).first).next;
  const int x = d.member(obj, "x~");
  EXPECT_EQ(d.pointer(x), "/a~1b/1/x~0");
  EXPECT_EQ(d.at(x).line, 3);
  EXPECT_EQ(d.text(x), "s\xc3\xa9");
}

TEST(JsonDoc, MalformedTextIsOneLineWithItsLine) {
  for (const auto& [text, line, what] : std::vector<std::tuple<std::string, int, std::string>>{
           {"{\"a\": 1,\n\"a\": 2}", 2, "duplicate key 'a'"},
           {"{\"a\": [1,\n 2,\n}", 3, "expected"},
           {"{\"a\": 1e999}", 1, "out of range"},
           {"[1] x", 1, "text after"},
           {"{\"a\": NaN}", 1, "unexpected character"}}) {
    try {
      ms::parse_json_doc(text, "t.json");
      ADD_FAILURE() << text;
    } catch (const ms::Error& e) {
      EXPECT_EQ(e.info().line, line) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
}

TEST(GraphErrors, NameTheFileLineAndPointerWithASuggestion) {
  const std::string j = "{\"root\": {\"op\": \"opUnion\", \"children\": [\n"
                        "  {\"sdf\": \"sdSphere\", \"r\": 1},\n"
                        "  {\"sdf\": \"sdShpere\", \"r\": 1}]}}";
  EXPECT_EQ(graph_error(j), "g.json:3: /root/children/1/sdf: unknown primitive 'sdShpere' (did you mean 'sdSphere'?)");
}

TEST(GraphErrors, EveryKindOfMistakeIsRefusedAtItsValue) {
  const auto node = [](const std::string& n) { return "{\"root\": " + n + "}"; };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {node("{\"sdf\": \"sdSphere\", \"radius\": 1}"), "/root/radius: unknown key 'radius'"},
      {node("{\"sdf\": \"sdSphere\"}"), "/root: missing parameter 'r'"},
      {node("{\"sdf\": \"sdBox\", \"b\": [1, 2]}"), "/root/b: 'b' must be an array of 3 numbers (it has 2)"},
      {node("{\"sdf\": \"sdSphere\", \"r\": -1}"), "/root/r: 'r' must not be negative"},
      {node("{\"sdf\": \"sdSphere\", \"r\": 1, \"scale\": 0}"), "/root/scale: 'scale' must be > 0"},
      {node("{\"sdf\": \"sdSphere\", \"r\": 1, \"matrix\": [2,0,0,0, 0,1,0,0, 0,0,1,0]}"),
       "/root/matrix: 'matrix' must be a rotation times a uniform scale"},
      {node("{\"sdf\": \"sdSphere\", \"r\": 1, \"matrix\": [-1,0,0,0, 0,1,0,0, 0,0,1,0]}"),
       "determinant is not positive"},
      {node("{\"op\": \"opUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 1}]}"),
       "/root/children: 'children' must be an array of two or more nodes"},
      {node("{\"op\": \"opSmoothUnoin\", \"children\": []}"), "did you mean 'opSmoothUnion'?"},
      {node("{\"op\": \"opSmoothUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 1}, "
            "{\"sdf\": \"sdSphere\", \"r\": 1}]}"),
       "/root: missing parameter 'k'"},
      {node("{\"sdf\": \"sdSphere\", \"r\": 1, \"material\": \"bal\"}"),
       "/root/material: unknown material 'bal' (did you mean 'ball'?)"},
      {node("{\"sdf\": \"sdPlane\", \"n\": [0, 1, 0], \"w\": 0}"), "the graph is unbounded"},
      {node("{\"sdf\": \"sdSphere\", \"r\": 1, \"rotate\": [0, 0, 0, 45]}"), "'rotate' needs a non-zero axis"},
  };
  for (const auto& [json, want] : cases) {
    const std::string e = graph_error(json);
    EXPECT_NE(e.find(want), std::string::npos) << "got: " << e << "\nwant: " << want;
    EXPECT_EQ(e.find('\n'), std::string::npos);
  }
}

// A degenerate chain nested 100,000 deep, loaded on a thread with a 256 KiB
// stack: any recursion over the depth would overflow it.
TEST(GraphDepth, AChainNested100000DeepLoadsOnASmallStack) {
  constexpr int kDepth = 100000;
  static std::string json;
  json = "{\"root\": ";
  for (int i = 0; i < kDepth; ++i)
    json += "{\"op\": \"opUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 0.1, \"translate\": [" +
            std::to_string(i % 7) + ", 0, 0]}, ";
  json += "{\"sdf\": \"sdSphere\", \"r\": 1}";
  for (int i = 0; i < kDepth; ++i) json += "]}";
  json += "}";
  static int primitives = 0;
  static std::string error;
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, 256 * 1024);
  pthread_t t;
  ASSERT_EQ(pthread_create(
                &t, &attr,
                [](void*) -> void* {
                  try {
                    primitives = graph_of(json).primitives;
                  } catch (const std::exception& e) {
                    error = e.what();
                  }
                  return nullptr;
                },
                nullptr),
            0);
  pthread_join(t, nullptr);
  pthread_attr_destroy(&attr);
  EXPECT_EQ(error, "");
  EXPECT_EQ(primitives, kDepth + 1);
}

TEST(GraphTransforms, ScaleThenRotateThenTranslateFromTheRootDown) {
  // The leaf's own scale 2, rotate 90 degrees about z, translate (1, 0, 0),
  // under a parent translated by (0, 0, 3).
  const ms::SceneGraph g = graph_of(
      "{\"root\": {\"op\": \"opUnion\", \"translate\": [0, 0, 3], \"children\": ["
      "{\"sdf\": \"sdBox\", \"b\": [1, 0.5, 0.25], \"scale\": 2, \"rotate\": [0, 0, 5, 90], \"translate\": [1, 0, 0]},"
      "{\"sdf\": \"sdSphere\", \"r\": 0.1}]}}");
  const ms::GraphNode& box = g.nodes[0];
  // Local x (half extent 1) becomes world y after the scale and rotation.
  const glm::vec3 local{1.0f, 0.0f, 0.0f};
  const glm::vec3 world = glm::vec3(1, 0, 3) + glm::vec3(0.0f, 2.0f, 0.0f);
  const glm::vec3 back = box.to_local * world + box.offset;
  EXPECT_NEAR(glm::length(back - local), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(box.scale, 2.0f);
  EXPECT_NEAR(box.box.min.x, 1.0f - 1.0f, 1e-3f);  // the 0.5 half extent, scaled, along x
  EXPECT_NEAR(box.box.max.y, 2.0f, 1e-3f);
  EXPECT_NEAR(box.box.min.z, 3.0f - 0.5f, 1e-3f);
}

TEST(GraphAnalysis, BoxesAndBoundsFollowTheOperators) {
  const auto root = [](const std::string& op, const std::string& extra) {
    return graph_of("{\"root\": {\"op\": \"" + op + "\"" + extra +
                    ", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 1}, "
                    "{\"sdf\": \"sdSphere\", \"r\": 1, \"translate\": [1.5, 0, 0]}]}}")
        .root_node();
  };
  EXPECT_NEAR(root("opUnion", "").box.max.x, 2.5f, 1e-3f);
  EXPECT_NEAR(root("opIntersection", "").box.min.x, 0.5f, 1e-3f);
  EXPECT_NEAR(root("opSubtraction", "").box.max.x, 1.0f, 1e-3f);
  EXPECT_NEAR(root("opSmoothUnion", ", \"k\": 0.4").box.max.x, 2.6f, 1e-3f);  // grown by k / 4
  EXPECT_FLOAT_EQ(root("opUnionChamfer", ", \"r\": 0.1").lipschitz, 1.41421356f);
  EXPECT_FLOAT_EQ(root("opSmoothUnion", ", \"k\": 0.4").lipschitz, 1.0f);
}

TEST(GraphAnalysis, AChainOf1000SmoothUnionsGrowsByOneBlendReach) {
  std::string json = "{\"root\": {\"op\": \"opSmoothUnion\", \"k\": 0.2, \"children\": [";
  for (int i = 0; i < 1000; ++i)
    json += std::string(i ? "," : "") + "{\"sdf\": \"sdSphere\", \"r\": 0.5, \"translate\": [" +
            std::to_string(i % 10) + ", " + std::to_string(i / 10 % 10) + ", " + std::to_string(i / 100) + "]}";
  const ms::GraphNode r = graph_of(json + "]}}").root_node();
  EXPECT_LE(r.slack, 0.2f + 1e-6f);
  EXPECT_NEAR(r.box.max.x, 9.5f + r.slack, 1e-3f);
  EXPECT_NEAR(r.box.min.y, -0.5f - r.slack, 1e-3f);
}

// Every 3D and 2D primitive and two-field combinator of sdf_shaders/, with
// its parameters and its claimed L, is in the vocabulary, and nothing else
// is.
TEST(GraphVocabulary, MatchesTheLibrarysSignaturesAndClaims) {
  std::string text;
  for (const char* f : {"primitives.glsl", "primitives2d.glsl", "primitives_cones.glsl", "primitives_poly.glsl",
                        "operators.glsl", "combinators.glsl", "modifiers.glsl"})
    text += ms::test::read_file(ms::test::source_dir() / "sdf_shaders" / f);
  const std::regex sig(R"(\[(?:[a-z ]+); L = ([0-9.]+)\]\n(?:#[^\n]*\n)?float ((?:sd2|ud2|sd|ud|op)[A-Z]\w*)\(([^)]*)\))");
  std::map<std::string, std::pair<std::string, float>> lib;  // name -> (parameters after p or a, b; L)
  for (std::sregex_iterator it(text.begin(), text.end(), sig), end; it != end; ++it) {
    const std::string name = (*it)[2], args = (*it)[3];
    const bool prim = name.rfind("op", 0) != 0, flat = name[2] == '2';
    const std::string head = !prim ? "float a, float b" : flat ? "vec2 p" : "vec3 p";
    if (args.rfind(head, 0) != 0) continue;  // one-field modifiers (graph_unary.h's, checked apart)
    std::string rest = args.substr(head.size());
    lib[name] = {rest, std::stof((*it)[1])};
  }
  EXPECT_EQ(lib.size(), ms::graph_primitives().size() + ms::graph_operators().size());
  std::set<std::string> seen;
  const auto check = [&](std::string_view name, const std::vector<ms::GraphParam>& params, float l) {
    std::string rest;
    for (const ms::GraphParam& p : params)
      if (p.points > 0)  // a vertex list: its count, then the array, as long in the GLSL as in the vocabulary
        rest += ", float n, vec2 " + std::string(p.name) + "[" + std::to_string(p.points) + "]";
      else
        rest += std::string(", ") + (p.size == 1 ? "float " : "vec" + std::to_string(p.size) + " ") + std::string(p.name);
    const auto it = lib.find(std::string(name));
    ASSERT_NE(it, lib.end()) << name << " is not in the library";
    EXPECT_EQ(it->second.first, rest) << name;
    EXPECT_NEAR(it->second.second, l, 1e-4f) << name;
    seen.insert(std::string(name));
  };
  for (const ms::GraphPrimitive& p : ms::graph_primitives()) check(p.name, p.params, p.lipschitz);
  for (const ms::GraphOperator& o : ms::graph_operators()) check(o.name, o.params, o.lipschitz);
  for (const auto& [name, _] : lib) EXPECT_TRUE(seen.count(name)) << name << " is missing from the vocabulary";
}

TEST(GraphScene, BoundsAndLipschitzFollowTheGraphUnlessDeclared) {
  TempDir dir;
  write_file(dir / "g.json",
             "{\"root\": {\"op\": \"opUnionChamfer\", \"r\": 0.1, \"children\": ["
             "{\"sdf\": \"sdSphere\", \"r\": 1}, {\"sdf\": \"sdBox\", \"b\": [1, 1, 1], \"translate\": [3, 0, 0]}]}}");
  const std::string base = "[scene]\ngraph = \"g.json\"\n[[materials]]\nname = \"m\"\n";
  write_file(dir / "a.toml", base);
  const ms::Scene a = ms::load_scene(dir / "a.toml");
  ASSERT_TRUE(a.graph);
  EXPECT_EQ(a.bounds.kind, ms::BoundsKind::box);
  EXPECT_GT(a.bounds.max.x, 4.1f);
  EXPECT_LT(a.bounds.max.x, 4.2f);
  EXPECT_FLOAT_EQ(a.quality.lipschitz, 1.41421356f);
  // A preset keeps the graph's bound; an explicit key wins over both.
  EXPECT_FLOAT_EQ(ms::with_preset(a.quality, "fast").lipschitz, 1.41421356f);
  write_file(dir / "b.toml", base + "[quality]\nlipschitz = 1.2\n[bounds]\nmin = [-1, -1, -1]\nmax = [3, 1, 1]\n");
  const ms::Scene b = ms::load_scene(dir / "b.toml");
  EXPECT_FLOAT_EQ(b.quality.lipschitz, 1.2f);
  EXPECT_EQ(ms::graph_overhang(b).substr(0, 15), "by 1.1 along +x");
}

TEST(GraphScene, AnInlineGraphNamesItsKeyAndExcludesMap) {
  TempDir dir;
  write_file(dir / "a.toml",
             "[scene]\n[scene.graph.root]\nop = \"opUnion\"\nchildren = [\n  { sdf = \"sdSphere\", r = 1.0 },\n"
             "  { sdf = \"sdBox\", b = [1.0, 1.0] },\n]\n[[materials]]\nname = \"m\"\n");
  try {
    ms::load_scene(dir / "a.toml");
    ADD_FAILURE();
  } catch (const ms::Error& e) {
    EXPECT_NE(std::string(e.what()).find("a.toml:6: scene.graph/root/children/1/b: 'b' must be an array of 3"),
              std::string::npos)
        << e.what();
  }
  write_file(dir / "b.toml", "[scene]\nmap = \"x.glsl\"\ngraph = \"g.json\"\n[[materials]]\nname = \"m\"\n");
  try {
    ms::load_scene(dir / "b.toml");
    ADD_FAILURE();
  } catch (const ms::Error& e) {
    EXPECT_NE(std::string(e.what()).find("'scene.map' and 'scene.graph' exclude each other"), std::string::npos);
  }
}

// The viewer's shader for a graph scene (AssembleOptions::bounds_uniforms)
// reads the bounds the graph's box gives from uniforms: a translate that
// moves the box leaves the interpreted shader's text as it was, the
// pruning grid's geometry included (it lives in the cell buffer).
TEST(GraphScene, BoundsAsUniformsKeepTheShaderAcrossAMove) {
  TempDir dir;
  const auto graph = [](const std::string& x) {
    return "{\"root\": {\"op\": \"opUnionColumns\", \"r\": 0.1, \"n\": 3, \"children\": ["
           "{\"sdf\": \"sdSphere\", \"r\": 1}, {\"sdf\": \"sdBox\", \"b\": [1, 1, 1], \"translate\": [" +
           x + ", 0, 0]}]}}";
  };
  write_file(dir / "s.toml", "[scene]\ngraph = \"g.json\"\n[[materials]]\nname = \"m\"\n");
  ms::AssembleOptions opts{fs::path(MARCH_SOURCE_DIR) / "sdf_shaders"};
  opts.specialize = ms::Specialization::folded;
  opts.graph_eval = ms::GraphEval::interpreter;
  std::string text[2][2];  // [bounds_uniforms][translate]
  for (int u = 0; u < 2; ++u)
    for (int x = 0; x < 2; ++x) {
      write_file(dir / "g.json", graph(x == 0 ? "3" : "4.5"));
      const ms::Scene scene = ms::load_scene(dir / "s.toml");
      opts.bounds_uniforms = u == 1;
      ms::prepare_graph_shape(scene, opts);
      text[u][x] = ms::assemble_scene(scene, opts).text;
    }
  EXPECT_NE(text[0][0], text[0][1]) << "folded, the box is in the text";
  EXPECT_EQ(text[1][0], text[1][1]);
  EXPECT_NE(text[1][0].find("#define BOUNDS_UNIFORMS 1\n"), std::string::npos);
  EXPECT_EQ(text[1][0].find("#define BOUNDS_A vec4("), std::string::npos);
  EXPECT_NE(text[0][0].find("#define BOUNDS_A vec4("), std::string::npos);
}

}  // namespace
