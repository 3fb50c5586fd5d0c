// A scene graph built from JSON text, and the one-line error a bad one
// gets: what the graph unit tests share.
//
//   ms::SceneGraph g = ms::test::graph_of(R"({"root": {"sdf": "sdSphere", "r": 1}})");
//   EXPECT_NE(ms::test::graph_error(bad).find("/root/op"), std::string::npos);
#pragma once
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "io/json_doc.h"
#include "scene/graph_build.h"

namespace ms::test {

inline SceneGraph graph_of(const std::string& json, std::vector<Material> materials = {{"ball"}, {"floor"}}) {
  const JsonDoc doc = parse_json_doc(json, "g.json");
  return build_graph(doc, doc.member(0, "root"), "g.json", "", materials);
}

inline std::string graph_error(const std::string& json) {
  try {
    graph_of(json);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "no error for " << json;
  return {};
}

}  // namespace ms::test
