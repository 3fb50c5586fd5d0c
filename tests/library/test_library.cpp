// The library's claims, verified on the GPU (llvmpipe in CI): every guarded
// function of sdf_shaders/ has a claim tag and at least one case in
// cases.toml, every case holds its claim, and docs/shader-library.md's
// table lists every claim as the tags state it (tools/library-table.sh
// fills it from this test's output, MARCH_LIBRARY_RESULTS=DIR).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "gl/context.h"
#include "verify.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::string kSource = MARCH_SOURCE_DIR;
const std::string kShaders = kSource + "/sdf_shaders";

const std::vector<Claim>& claims() {
  static const std::vector<Claim> c = library_claims(kShaders);
  return c;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> c = load_cases(kSource + "/tests/library/cases.toml", claims());
  return c;
}

// The test groups: one ctest each, so they run in parallel.
std::string group_of(const std::string& file) {
  if (file == "primitives2d.glsl") return "primitives2d";
  if (file.rfind("primitives", 0) == 0) return "primitives";
  if (file == "operators.glsl" || file == "combinators.glsl") return "operators";
  if (file == "domain.glsl") return "domain";
  if (file == "modifiers.glsl") return "modifiers";
  return "noise";
}

std::string file_of(const std::string& function) {
  for (const Claim& c : claims())
    if (c.function == function) return c.file;
  return {};
}

class LibraryClaims : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryClaims, HoldInEveryCase) {
  std::unique_ptr<Context> ctx = create_headless_context(Backend::automatic);
  nlohmann::json out = nlohmann::json::array();
  int n = 0;
  for (const Case& c : cases()) {
    if (group_of(file_of(c.function)) != GetParam()) continue;
    ++n;
    const std::string label = c.function + (c.condition.empty() ? "" : " (" + c.condition + ")");
    CaseResult r;
    try {
      r = verify_case(c, kShaders);
    } catch (const std::exception& e) {
      ADD_FAILURE() << label << ": " << e.what();
      continue;
    }
    EXPECT_TRUE(r.passed()) << label << " [" << c.kind << "; L = " << c.lipschitz << "]: "
                            << r.lipschitz_violations << " Lipschitz, " << r.distance_violations << " distance and "
                            << r.sign_violations << " sign/range failures; first: " << r.first_failure;
    // A case that measured nothing verifies nothing.
    if (c.kind == "index" || c.kind == "helper") EXPECT_GT(r.sign_points, 1000) << label;
    else EXPECT_GT(r.lipschitz_pairs, 1000) << label;
    if (c.kind != "noise" && c.kind != "index" && c.kind != "helper") {
      EXPECT_GT(r.distance_points, 200) << label << ": too few points to compare with the surface";
      EXPECT_GT(r.sign_points, 1000) << label;
    }
    nlohmann::json j = to_json(c, r);
    j["file"] = file_of(c.function);
    j["renderer"] = ctx->info().renderer;
    out.push_back(j);
  }
  EXPECT_GT(n, 0) << "no cases for " << GetParam();
  if (const char* dir = std::getenv("MARCH_LIBRARY_RESULTS")) {
    std::ofstream(fs::path(dir) / (GetParam() + ".json")) << out.dump(1) << "\n";
  }
}

INSTANTIATE_TEST_SUITE_P(Groups, LibraryClaims,
                         ::testing::Values("primitives", "primitives2d", "operators", "domain", "modifiers", "noise"));

TEST(LibraryClaims, EveryFunctionHasAClaimAndACase) {
  ASSERT_GE(claims().size(), 80u);
  for (const Claim& c : claims()) {
    int plain = 0;
    for (const Case& k : cases()) plain += k.function == c.function && k.condition.empty();
    EXPECT_GE(plain, 1) << c.file << ":" << c.line << ": " << c.function << " has no case without a condition in cases.toml";
  }
  int prims = 0;
  for (const Claim& c : claims()) prims += (c.function.rfind("sd", 0) == 0 || c.function.rfind("ud", 0) == 0) &&
                                           c.function.rfind("sd2", 0) != 0 && c.function.rfind("ud2", 0) != 0;
  EXPECT_GE(prims, 30) << "3D primitives";
  if (const char* dir = std::getenv("MARCH_LIBRARY_RESULTS")) {  // for tools/library-table.sh
    nlohmann::json out = nlohmann::json::array();
    for (const Claim& c : claims())
      out.push_back({{"function", c.function}, {"file", c.file}, {"claim", c.kind}, {"lipschitz", c.lipschitz}});
    std::ofstream(fs::path(dir) / "claims.json") << out.dump(1) << "\n";
  }
}

// docs/shader-library.md between the markers: one row per claim, in library
// order, with the claim and L as tagged (the measured columns come from the
// test's output through tools/library-table.sh).
TEST(LibraryClaims, TheDocsTableStatesEveryClaim) {
  std::ifstream in(kSource + "/docs/shader-library.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const std::string begin = "<!-- library-table:begin -->", end = "<!-- library-table:end -->";
  const size_t b = doc.find(begin), e = doc.find(end);
  ASSERT_TRUE(b != std::string::npos && e != std::string::npos) << "docs/shader-library.md lacks the table markers";
  // | `function` | file | claim | `L` | ...; a configuration's row starts with "| ↳".
  const std::regex row(R"(^\| `(\w+)` \| [^|]+ \| ([^|]+) \| `([^`]*)` \|)");
  std::vector<std::tuple<std::string, std::string, std::string>> rows;
  std::istringstream lines(doc.substr(b, e - b));
  std::string line;
  std::smatch m;
  while (std::getline(lines, line))
    if (std::regex_search(line, m, row)) rows.emplace_back(m[1], m[2], m[3]);
  std::vector<std::tuple<std::string, std::string, std::string>> want;
  for (const Claim& c : claims()) want.emplace_back(c.function, c.kind, c.lipschitz.empty() ? "-" : c.lipschitz);
  EXPECT_EQ(rows, want) << "regenerate the table: tools/library-table.sh";
}

}  // namespace
}  // namespace ms::test

namespace ms::test {
namespace {

// The verification can fail: false claims of each kind are caught.
TEST(LibraryHarness, CatchesFalseClaims) {
  std::unique_ptr<Context> ctx = create_headless_context(Backend::automatic);
  auto make = [](const std::string& kind, double l, const std::string& f, const std::string& inside,
                 const std::string& helpers = "") {
    Case c;
    c.function = "false claim";
    c.kind = kind;
    c.lipschitz = l;
    c.box = {glm::vec3(-1.2f), glm::vec3(1.2f)};
    c.src = {f, inside, "false", "0.0", "vec3(0.0)", helpers};
    return c;
  };
  const std::string in_box = "all(lessThan(abs(p), vec3(0.8, 0.5, 0.3)))";
  struct Expect {
    Case c;
    bool lipschitz, distance, sign;  // which checks must fail (others may fail too)
  };
  const std::vector<Expect> wrong = {
      // a bound (the max norm) claimed exact: too small off the faces
      {make("exact", 1.0, "sdBoxCheap(p, vec3(0.8, 0.5, 0.3))", in_box), false, true, false},
      // an exact distance with a wrong membership test
      {make("exact", 1.0, "sdSphere(p, 0.8)", "length(p) < 0.85"), false, false, true},
      // a twist stated 1-Lipschitz
      {make("bound", 1.0, "sdBox(domTwist(p, 1.2), vec3(0.55, 0.8, 0.2))", "false"), true, false, false},
      // a rippled sphere claimed exact (its slope is not 1)
      {make("exact", 1.3, "sdSphere(p, 0.8) + 0.01 * sin(20.0 * p.x)", "length(p) < 0.8"), false, true, false},
      // the first-order ellipsoid estimate inside, claimed a bound
      {make("bound", 1.0, "ell(p)", "dot(p / R, p / R) < 1.0",
            "const vec3 R = vec3(0.9, 0.5, 0.3);\n"
            "float ell(vec3 p) { float k0 = length(p / R); return k0 * (k0 - 1.0) / length(p / (R * R)); }\n"),
       true, true, false},
      // value noise scaled past its range
      {make("noise", 3.03 * 2.0 * 3.0, "2.0 * noiseValue(p * 3.0)", "false"), false, false, true},
  };
  for (const Expect& e : wrong) {
    const CaseResult r = verify_case(e.c, kShaders);
    EXPECT_FALSE(r.passed()) << e.c.src.f;
    if (e.lipschitz) EXPECT_GT(r.lipschitz_violations, 0) << e.c.src.f << ": " << r.first_failure;
    if (e.distance) EXPECT_GT(r.distance_violations, 0) << e.c.src.f << ": " << r.first_failure;
    if (e.sign) EXPECT_GT(r.sign_violations, 0) << e.c.src.f << ": " << r.first_failure;
  }
}

}  // namespace
}  // namespace ms::test
