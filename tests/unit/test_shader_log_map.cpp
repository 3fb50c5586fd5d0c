// parse_info_log(): driver log formats, and the round trip assembled line ->
// driver location -> file:line through the #line directives preprocess() emits.
#include <gtest/gtest.h>

#include "preprocess/log_map.h"
#include "preprocess/preprocess.h"
#include "test_shader_util.h"

namespace ms {
namespace {

namespace fs = std::filesystem;
using test::shader_data;

ShaderSource two_files() {
  ShaderSource s;
  s.files = {"root.frag", "lib/a.glsl"};
  return s;
}

const ShaderDiagnostic* first_located(const std::vector<ShaderDiagnostic>& d) {
  for (const auto& x : d)
    if (!x.file.empty()) return &x;
  return nullptr;
}

TEST(ShaderLogMap, MesaFormat) {
  auto d = parse_info_log("1:12(5): error: `foo' undeclared\n0:3(1): warning: unused: x\n", two_files());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].file, "lib/a.glsl");
  EXPECT_EQ(d[0].line, 12);
  EXPECT_EQ(d[0].severity, "error");
  EXPECT_EQ(d[0].message, "`foo' undeclared");
  EXPECT_EQ(d[1].file, "root.frag");
  EXPECT_EQ(d[1].severity, "warning");
  EXPECT_EQ(d[1].message, "unused: x");
  // Mesa's preprocessor spells its severity in two words.
  auto p = parse_info_log("1:4(1): preprocessor error: #error boom", two_files());
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].severity, "error");
  EXPECT_EQ(p[0].message, "#error boom");
}

TEST(ShaderLogMap, NvidiaFormat) {
  auto d = parse_info_log("1(7) : error C0000: syntax error, unexpected '}'\r\n", two_files());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].file, "lib/a.glsl");
  EXPECT_EQ(d[0].line, 7);
  EXPECT_EQ(d[0].severity, "error");
  EXPECT_EQ(d[0].message, "syntax error, unexpected '}'");
}

TEST(ShaderLogMap, GlslangFormatDropsSummary) {
  auto d = parse_info_log("ERROR: 1:9: 'bar' : undeclared identifier \n"
                          "ERROR: 0:2: '' :  syntax error, unexpected IDENTIFIER\n"
                          "ERROR: 2 compilation errors.  No code generated.\n\n",
                          two_files());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].file, "lib/a.glsl");
  EXPECT_EQ(d[0].line, 9);
  EXPECT_EQ(d[0].message, "'bar' : undeclared identifier");
  EXPECT_EQ(d[1].message, "syntax error, unexpected IDENTIFIER");
}

TEST(ShaderLogMap, UnknownAndLocationlessLinesPassThrough) {
  auto d = parse_info_log("error: linking with uncompiled shader\nsomething odd happened\n7:1(1): error: x\n",
                          two_files());
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].file, "");
  EXPECT_EQ(d[0].severity, "error");
  EXPECT_EQ(d[1].file, "");
  EXPECT_EQ(d[1].severity, "");
  EXPECT_EQ(d[1].message, "something odd happened");
  // A source-string number we never emitted keeps its raw location.
  EXPECT_EQ(d[2].file, "");
  EXPECT_EQ(d[2].message, "7:1: x");
}

TEST(ShaderLogMap, MapLocationDecodesTheLineStride) {
  const ShaderSource s = two_files();
  EXPECT_EQ(map_location(s, 0, 7).file, "root.frag");
  EXPECT_EQ(map_location(s, 0, kLineStride + 7).file, "lib/a.glsl");  // Mesa: string 0, encoded line
  EXPECT_EQ(map_location(s, 0, kLineStride + 7).line, 7);
  EXPECT_EQ(map_location(s, 1, kLineStride + 7).file, "lib/a.glsl");
  EXPECT_EQ(map_location(s, 0, 2LL * kLineStride + 1).file, "");  // no file 2
  EXPECT_EQ(map_location(s, 5, 3).file, "");
}

TEST(ShaderLogMap, FormatOneLinePerDiagnostic) {
  std::vector<ShaderDiagnostic> d = {{"a.glsl", 3, "error", "bad"}, {"", 0, "", "raw text"}};
  EXPECT_EQ(format_diagnostics(d), "a.glsl:3: error: bad\nraw text\n");
}

// A synthetic Mesa log for an assembled line: locate it as a compiler would,
// then map it back. Covers the way in and out of two include levels.
TEST(ShaderLogMap, SyntheticMesaLogMapsAcrossTwoIncludeLevels) {
  const fs::path dir = shader_data("mapping");
  const std::string root = "#version 450 core\n#include \"level1.glsl\"\nfloat root_after = undefined_MARK_ROOT;\n";
  ShaderSource s = preprocess(root, "root.frag", dir, {});
  const fs::path l1 = dir / "level1.glsl", l2 = dir / "deeper/level2.glsl";
  struct Case { std::string marker; std::string file; int line; };
  const Case cases[] = {
      {"undefined_MARK_L2", display_path(l2), test::line_containing(test::read_file(l2), "undefined_MARK_L2")},
      {"undefined_MARK_L1", display_path(l1), test::line_containing(test::read_file(l1), "undefined_MARK_L1")},
      {"level1_before", display_path(l1), test::line_containing(test::read_file(l1), "level1_before")},
      {"undefined_MARK_ROOT", "root.frag", test::line_containing(root, "undefined_MARK_ROOT")},
  };
  for (const Case& c : cases) {
    const int n = test::line_containing(s.text, c.marker);
    ASSERT_GT(n, 0) << c.marker;
    test::Where w = test::compiler_location(s.text, n);
    ASSERT_GE(w.string_no, 0) << c.marker;
    // As a parser error (string number kept) and as Mesa reports AST errors (string 0).
    for (int string_no : {w.string_no, 0}) {
      const std::string log = std::to_string(string_no) + ":" + std::to_string(w.line) + "(3): error: boom\n";
      auto d = parse_info_log(log, s);
      ASSERT_EQ(d.size(), 1u);
      EXPECT_EQ(d[0].file, c.file) << c.marker << " " << log;
      EXPECT_EQ(d[0].line, c.line) << c.marker << " " << log;
    }
  }
}

// glslang stops at the first global-scope error, so each variant switches
// off the errors before the one it checks.
TEST(ShaderLogMap, GlslangErrorInSecondLevelIncludeMapsToItsLine) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  const fs::path dir = shader_data("mapping");
  const fs::path l1 = dir / "level1.glsl", l2 = dir / "deeper/level2.glsl";
  const std::string tail = "#include \"level1.glsl\"\nfloat root_after = undefined_MARK_ROOT;\nvoid main() {}\n";
  struct Case { std::string defines, file, marker, text; };
  const Case cases[] = {
      {"", display_path(l2), "undefined_MARK_L2", test::read_file(l2)},
      {"#define SKIP_L2_ERROR\n", display_path(l1), "undefined_MARK_L1", test::read_file(l1)},
      {"#define SKIP_L2_ERROR\n#define SKIP_L1_ERROR\n", "root.frag", "undefined_MARK_ROOT", ""},
  };
  for (const Case& c : cases) {
    const std::string root = "#version 450 core\n" + c.defines + tail;
    ShaderSource s = preprocess(root, "root.frag", dir, {});
    test::GlslangResult r = test::run_glslang(s.text, "twolevel");
    EXPECT_NE(r.status, 0) << r.output;
    const std::vector<ShaderDiagnostic> d = parse_info_log(r.output, s);
    const ShaderDiagnostic* first = first_located(d);
    ASSERT_NE(first, nullptr) << r.output;
    EXPECT_EQ(first->file, c.file) << r.output;
    EXPECT_EQ(first->line, test::line_containing(c.text.empty() ? root : c.text, c.marker)) << r.output;
    EXPECT_NE(first->message.find(c.marker), std::string::npos) << first->message;
  }
}

// A compiler skips #line directives in an inactive #if group but still counts
// its lines; the re-sync after #endif must keep later lines exact.
TEST(ShaderLogMap, GlslangLineStaysExactAfterInactiveInclude) {
  if (!test::have_glslang()) GTEST_SKIP() << "glslangValidator not on PATH";
  const std::string roots[] = {
      "#version 450 core\n#if 0\n#include \"big.glsl\"\n#endif\n"
      "float after = undefined_MARK_AFTER;\nvoid main() {}\n",
      "#version 450 core\n#if 0\n#include \"big.glsl\"\n#else\n#include \"big.glsl\"\n#endif\n"
      "float after = undefined_MARK_AFTER;\nvoid main() {}\n",
  };
  for (const std::string& root : roots) {
    ShaderSource s = preprocess(root, "root.frag", shader_data("cond"), {});
    test::GlslangResult r = test::run_glslang(s.text, "cond");
    auto d = parse_info_log(r.output, s);
    const ShaderDiagnostic* first = first_located(d);
    ASSERT_NE(first, nullptr) << r.output;
    EXPECT_EQ(first->file, "root.frag");
    EXPECT_EQ(first->line, test::line_containing(root, "undefined_MARK_AFTER")) << r.output << s.text;
  }
}

}  // namespace
}  // namespace ms
