// docs/scene-graph.md's "Coverage against fogleman/sdf" (written by
// tools/coverage.py): every node the table shows builds with the graph
// builder, every left-out row says why, and every picture it names exists.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "graph_of.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

struct CoverageRow {
  int line = 0;
  std::string name, node, notes, picture;
};

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// A table row's cells, split at pipes not escaped as \|.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|' && line[i - 1] != '\\') {
      out.push_back(trimmed(cur));
      cur.clear();
    } else {
      cur += line[i];
    }
  }
  return out;
}

// "`sphere(radius=1, ...)`" names sphere; "smooth_union: `union(...)`" smooth_union.
std::string function_name(const std::string& cell) {
  if (cell.rfind("`", 0) == 0) return cell.substr(1, cell.find('(') - 1);
  return cell.substr(0, cell.find(": `"));
}

// The function rows between the coverage markers (not the header, the
// separator or a group's heading row).
std::vector<CoverageRow> coverage_rows() {
  std::istringstream doc(read_file(fs::path(MARCH_SOURCE_DIR) / "docs" / "scene-graph.md"));
  std::vector<CoverageRow> rows;
  bool in = false;
  std::string line;
  for (int n = 1; std::getline(doc, line); ++n) {
    if (line == "<!-- coverage:begin -->") in = true;
    if (line == "<!-- coverage:end -->") in = false;
    if (!in || line.rfind("| ", 0) != 0 || line.rfind("| fogleman/sdf |", 0) == 0 || line.rfind("| **", 0) == 0)
      continue;
    const std::vector<std::string> c = cells(line);
    EXPECT_EQ(c.size(), 4u) << "docs/scene-graph.md:" << n << ": a coverage row of " << c.size() << " cells";
    if (c.size() == 4) rows.push_back({n, function_name(c[0]), c[1], c[2], c[3]});
  }
  return rows;
}

TEST(GraphCoverage, EveryFunctionOfFoglemansReferenceHasOneRow) {
  // fogleman/sdf README, "Function Reference", in its order.
  const std::vector<std::string> reference = {
      "sphere", "box", "rounded_box", "wireframe_box", "torus", "capsule", "capped_cylinder", "rounded_cylinder",
      "capped_cone", "rounded_cone", "ellipsoid", "pyramid", "tetrahedron", "octahedron", "dodecahedron",
      "icosahedron", "plane", "slab", "cylinder", "translate", "scale", "scale (tuple)", "rotate", "orient", "union",
      "difference", "intersection", "smooth_union", "smooth_difference", "smooth_intersection", "repeat",
      "circular_array", "blend", "dilate", "erode", "shell", "elongate", "twist", "bend", "bend_linear",
      "bend_radial", "transition_linear", "transition_radial", "extrude", "extrude_to", "revolve", "slice", "circle",
      "line", "rectangle", "rounded_rectangle", "equilateral_triangle", "hexagon", "rounded_x", "polygon"};
  std::vector<std::string> names;
  for (const CoverageRow& r : coverage_rows()) names.push_back(r.name);
  EXPECT_EQ(names, reference);
}

TEST(GraphCoverage, EveryNodeInTheTableBuilds) {
  int built = 0;
  for (const CoverageRow& r : coverage_rows()) {
    if (r.node == "—") continue;
    ASSERT_TRUE(r.node.size() > 2 && r.node.front() == '`' && r.node.back() == '`')
        << "docs/scene-graph.md:" << r.line << ": " << r.name << "'s node is not one code span";
    const std::string json = R"({"root": )" + r.node.substr(1, r.node.size() - 2) + "}";
    try {
      const SceneGraph g = graph_of(json);
      EXPECT_FALSE(g.root_node().box.empty()) << r.name;
      ++built;
    } catch (const Error& e) {
      ADD_FAILURE() << "docs/scene-graph.md:" << r.line << ": " << r.name << ": " << e.what();
    }
  }
  EXPECT_GE(built, 40);  // the rows are still found: most functions have a node
}

TEST(GraphCoverage, LeftOutRowsSayWhyAndShowNoPicture) {
  int left_out = 0;
  for (const CoverageRow& r : coverage_rows()) {
    if (r.node != "—") continue;
    ++left_out;
    const std::string lead = "**Left out.** ";
    EXPECT_EQ(r.notes.rfind(lead, 0), 0u) << "docs/scene-graph.md:" << r.line << ": " << r.name;
    // A reason, not a placeholder: what it does and what it would need.
    EXPECT_GT(r.notes.size(), lead.size() + 60) << "docs/scene-graph.md:" << r.line << ": " << r.name;
    EXPECT_EQ(r.picture, "—") << r.name;
  }
  EXPECT_GT(left_out, 0);
}

TEST(GraphCoverage, EveryPictureTheTableNamesExistsAndNoOther) {
  const fs::path docs = fs::path(MARCH_SOURCE_DIR) / "docs";
  std::set<std::string> seen;
  for (const CoverageRow& r : coverage_rows()) {
    if (r.node == "—") continue;
    const std::string open = "](", close = ".png)";
    const std::size_t a = r.picture.find(open), b = r.picture.find(close);
    ASSERT_TRUE(r.picture.rfind("![", 0) == 0 && a != std::string::npos && b != std::string::npos)
        << "docs/scene-graph.md:" << r.line << ": " << r.name << " has no picture";
    const std::string path = r.picture.substr(a + 2, b + 4 - (a + 2));
    EXPECT_EQ(path.rfind("images/coverage/", 0), 0u) << path;
    EXPECT_TRUE(seen.insert(path).second) << path << " is named twice";
    EXPECT_TRUE(fs::is_regular_file(docs / path)) << "docs/scene-graph.md:" << r.line << ": " << path;
  }
  // And no picture is left behind by a row that is gone or renamed.
  for (const auto& e : fs::directory_iterator(docs / "images" / "coverage"))
    EXPECT_TRUE(seen.count("images/coverage/" + e.path().filename().string()))
        << "docs/images/coverage/" << e.path().filename().string() << " is not in the table";
}

}  // namespace
}  // namespace ms::test
