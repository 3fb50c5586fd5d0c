// The graph reader against hostile input: the JSON document's size is
// checked from the text before it is allocated, and a value costs a fixed
// few bytes; a finite graph too large for float is refused at the node
// that overflows, with its cause, not called unbounded; names and pointers
// in error lines are cut, so a megabyte key is not echoed.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "files.h"
#include "io/json_doc.h"
#include "scene/graph_build.h"
#include "scene/load.h"

namespace {

using ms::test::write_file;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ms::Error& e) {
    EXPECT_EQ(e.code(), ms::Exit::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

std::string graph_error(const std::string& json) {
  return error_of([&] {
    const ms::JsonDoc doc = ms::parse_json_doc(json, "g.json");
    ms::build_graph(doc, doc.member(0, "root"), "g.json", "", {ms::Material{"m"}});
  });
}

std::string node(const std::string& body) { return "{\"root\": " + body + "}"; }

TEST(JsonBudget, AValueCostsAFewBytesWhateverItHolds) {
  // Strings live in one pool: an empty array costs what a number does.
  EXPECT_LE(sizeof(ms::JsonValue), 56u);
  const ms::JsonDoc d = ms::parse_json_doc("{\"key\": [\"text\", 1, [], {}]}", "t.json");
  EXPECT_EQ(d.values.size(), 6u);
  EXPECT_EQ(d.strings, "keytext");
}

TEST(JsonBudget, DepthAndCountAreRefusedByNameBeforeTheParse) {
  const double budget = 1 << 20;  // 1 MiB
  std::string deep(100000, '[');
  std::string wide = "[";
  for (int i = 0; i < 100000; ++i) wide += "{},";
  wide += "{}]";
  for (const std::string* text : {&deep, &wide}) {
    const std::string e = error_of([&] { ms::parse_json_doc(*text, "big.json", {}, budget); });
    EXPECT_EQ(e.rfind("big.json: the JSON needs ", 0), 0u) << e;
    EXPECT_NE(e.find("over the 1 MiB memory budget"), std::string::npos) << e;
  }
  EXPECT_NE(error_of([&] { ms::parse_json_doc(deep, "big.json", {}, budget); }).find("nested up to 100000 deep"),
            std::string::npos);
  // What the caller keeps per value counts too: 100,001 values of 10 KiB.
  EXPECT_NE(error_of([&] { ms::parse_json_doc(wide, "w.json", {10240, 0}, 2e9); }).find("memory budget"),
            std::string::npos);
  // Within the budget the same texts parse.
  EXPECT_EQ(ms::parse_json_doc(wide, "w.json", {}, 1e9).values.size(), 100002u);
}

TEST(GraphOverflow, AHugeRadiusIsNamedAtItsNodeNotCalledUnbounded) {
  const std::string e = graph_error(node("{\"op\": \"opUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 1}, "
                                         "{\"sdf\": \"sdSphere\", \"r\": 1e30}]}"));
  EXPECT_NE(e.find("g.json:1: /root/children/1: its box reaches 1e+30 along x, past the 1e+18"), std::string::npos)
      << e;
  EXPECT_EQ(e.find("unbounded"), std::string::npos) << e;
}

TEST(GraphOverflow, NestedScalesAreNamedAtTheScaleThatOverflows) {
  const auto nested = [](const std::string& s) {
    return node("{\"op\": \"opUnion\", \"scale\": " + s + ", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 1}, "
                "{\"sdf\": \"sdSphere\", \"r\": 1, \"scale\": " + s + "}]}");
  };
  const std::string big = graph_error(nested("1e30"));
  EXPECT_NE(big.find("/root/scale: the scales from the root down to this node multiply to 1e+30, past the 1e+18"),
            std::string::npos) << big;
  const std::string tiny = graph_error(nested("1e-30"));
  EXPECT_NE(tiny.find("/root/scale: the scales from the root down to this node multiply to 1e-30, under the 1e-18"),
            std::string::npos) << tiny;
  // Each within range, together past it: the inner scale is named.
  const std::string two = graph_error(nested("1e10"));
  EXPECT_NE(two.find("/root/children/1/scale: the scales from the root down to this node multiply to 1e+20"),
            std::string::npos) << two;
  for (const std::string* e : {&big, &tiny, &two}) EXPECT_EQ(e->find("unbounded"), std::string::npos) << *e;
  // An infinite plane is still what it is.
  EXPECT_NE(graph_error(node("{\"sdf\": \"sdPlane\", \"n\": [0, 1, 0], \"w\": 0}")).find("unbounded"),
            std::string::npos);
}

TEST(GraphErrors, MegabyteNamesAreCutInTheLine) {
  const std::string big(1 << 20, 'q');
  ms::test::TempDir dir;
  const std::vector<std::string> errors = {
      graph_error(node("{\"sdf\": \"sdSphere\", \"r\": 1, \"" + big + "\": 1}")),  // unknown key
      graph_error(node("{\"sdf\": \"" + big + "\", \"r\": 1}")),                   // unknown primitive
      graph_error(node("{\"op\": \"" + big + "\", \"children\": []}")),           // unknown operator
      error_of([&] {  // a file's top level holds only "root"
        write_file(dir / "g.json", "{\"" + big + "\": 1, \"root\": {}}");
        std::vector<ms::Material> mats{ms::Material{"m"}};
        ms::load_graph_file(dir / "g.json", mats);
      }),
      graph_error("{\"root\": {\"" + big + "\": 1, \"" + big + "\": 2}}"),         // duplicate
      graph_error(node("{\"sdf\": \"sdSphere\", \"r\": 1" + std::string(400, '0') + "e999}")),
      error_of([&] {
        ms::parse_scene("[scene]\n[scene.graph]\n\"" + big + "\" = 1\n[[materials]]\nname = \"m\"\n", "s.toml");
      }),
  };
  for (const std::string& e : errors) {
    EXPECT_LT(e.size(), 300u) << e.substr(0, 400);
    EXPECT_TRUE(e.find("qqq...") != std::string::npos || e.find("000...") != std::string::npos) << e.substr(0, 400);
  }
}

TEST(GraphErrors, APointerDeeperThanALineShowsItsEnds) {
  std::string json = "{\"root\": ";
  for (int i = 0; i < 2000; ++i) json += "{\"op\": \"opUnion\", \"children\": [{\"sdf\": \"sdSphere\", \"r\": 1}, ";
  json += "{\"sdf\": \"sdShpere\", \"r\": 1}";
  for (int i = 0; i < 2000; ++i) json += "]}";
  json += "}";
  const std::string e = graph_error(json);
  EXPECT_LT(e.size(), 300u) << e.substr(0, 400);
  EXPECT_NE(e.find("g.json:1: /root/children/1/children/.../1/children/1/children/1/children/1/sdf: unknown primitive"),
            std::string::npos) << e;
}

}  // namespace
