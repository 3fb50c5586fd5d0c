// preprocess() with the driver model on (preprocess/macro_engine.h): include
// diamonds stop at the size budget, include guards and #pragma once make
// them linear, includes in dead #if groups are not read, a live #error
// fails, and a user's #line renumbers its own file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "files.h"
#include "preprocess/log_map.h"
#include "preprocess/preprocess.h"

namespace ms {
namespace {

namespace fs = std::filesystem;

class PreprocessBudget : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::canonical(tmp_dir.path());
    old_cwd = fs::current_path();
    fs::current_path(dir);  // display paths are then plain file names
  }
  void TearDown() override { fs::current_path(old_cwd); }
  void put(const std::string& name, const std::string& text) { std::ofstream(dir / name, std::ios::binary) << text; }
  ShaderSource pp(const std::string& root) { return preprocess(root, "root.frag", dir, {}); }
  std::string error_of(const std::string& root) {
    try {
      pp(root);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  // f0 .. f<n-1> each include the next twice; f<n> is a leaf. With `guard`,
  // each file is wrapped in #ifndef F<i> / #define F<i> / #endif.
  void diamond(int n, bool guard) {
    for (int i = 0; i <= n; ++i) {
      std::string body = i < n ? "#include \"f" + std::to_string(i + 1) + ".glsl\"\n#include \"f" +
                                     std::to_string(i + 1) + ".glsl\"\n"
                               : "float leaf() { return 1.0; }\n";
      if (guard) body = "// guarded\n#ifndef F" + std::to_string(i) + "\n#define F" + std::to_string(i) + "\n" + body +
                        "#endif\n";
      put("f" + std::to_string(i) + ".glsl", body);
    }
  }
  test::TempDir tmp_dir;
  fs::path dir, old_cwd;
};

size_t count_of(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
  return n;
}

TEST_F(PreprocessBudget, AnIncludeDiamondStopsAtTheSizeBudgetNamingTheFile) {
  diamond(40, false);  // 2^40 copies of the leaf
  const std::string err = error_of("#include \"f0.glsl\"\n");
  EXPECT_NE(err.find("the shader is larger than 8 MiB with its includes expanded"), std::string::npos) << err;
  EXPECT_NE(err.find("'f40.glsl' is included"), std::string::npos) << err;
  EXPECT_NE(err.find("guard it with #pragma once or #ifndef"), std::string::npos) << err;
}

TEST_F(PreprocessBudget, IncludeGuardsAndPragmaOnceMakeADiamondLinear) {
  diamond(40, true);
  const ShaderSource s = pp("#include \"f0.glsl\"\n");
  EXPECT_EQ(count_of(s.text, "float leaf()"), 1u);
  EXPECT_EQ(count_of(s.text, "skipped: include guard F40"), 1u);
  // The guard is honoured only while its macro is defined.
  put("g.glsl", "#ifndef G\n#define G\nfloat g;\n#endif\n");
  EXPECT_EQ(count_of(pp("#include \"g.glsl\"\n#undef G\n#include \"g.glsl\"\n").text, "float g;"), 2u);
  // Code after the guard's #endif means no guard.
  put("h.glsl", "#ifndef H\n#define H\nfloat h;\n#endif\nfloat after;\n");
  EXPECT_EQ(count_of(pp("#include \"h.glsl\"\n#include \"h.glsl\"\n").text, "float h;"), 2u);
}

TEST_F(PreprocessBudget, IncludesInDeadGroupsAreNotRead) {
  const ShaderSource s = pp("#define USE_B 0\n#if USE_B\n#include \"missing.glsl\"\n#endif\nfloat a;\n");
  EXPECT_NE(s.text.find("skipped: its #if group is not compiled"), std::string::npos);
  EXPECT_NE(error_of("#define USE_B 1\n#if USE_B\n#include \"missing.glsl\"\n#endif\n").find("cannot find include"),
            std::string::npos);
  // An include whose group depends on a driver macro is read.
  put("ext.glsl", "float ext;\n");
  EXPECT_NE(pp("#ifdef GL_ARB_gpu_shader_fp64\n#include \"ext.glsl\"\n#endif\n").text.find("float ext;"),
            std::string::npos);
}

TEST_F(PreprocessBudget, ALiveErrorFailsAtItsFileAndLine) {
  put("lib.glsl", "// lib\n#ifndef READY\n#error define READY before including lib.glsl\n#endif\n");
  const std::string err = error_of("#include \"lib.glsl\"\n");
  EXPECT_EQ(err, "lib.glsl:3: #error define READY before including lib.glsl");
  EXPECT_EQ(error_of("#define READY\n#include \"lib.glsl\"\n"), "");
}

TEST_F(PreprocessBudget, AUserLineDirectiveRenumbersItsOwnFile) {
  put("map.glsl", "float a;\n#line 500\nfloat b = undefined_thing;\n");
  const ShaderSource s = pp("#version 450 core\n#include \"map.glsl\"\nvoid main() {}\n");
  EXPECT_NE(s.text.find("#line 100500 1\nfloat b"), std::string::npos) << s.text;
  // A Mesa-style log for that line decodes to map.glsl:500, not the root.
  const std::vector<ShaderDiagnostic> d = parse_info_log("0:100500(11): error: `undefined_thing' undeclared\n", s);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].file, "map.glsl");
  EXPECT_EQ(d[0].line, 500);
  // Errors of ours count from it too; beyond the mapping is an error.
  put("map2.glsl", "#line 40\n#error here\n");
  EXPECT_EQ(error_of("#include \"map2.glsl\"\n"), "map2.glsl:40: #error here");
  put("map3.glsl", "#line 100000\nfloat c;\n");
  EXPECT_NE(error_of("#include \"map3.glsl\"\n").find("beyond marchstudio's line mapping"), std::string::npos);
}

}  // namespace
}  // namespace ms
