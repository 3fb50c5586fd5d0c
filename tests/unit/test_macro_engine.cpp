// preprocess/macro_engine.h: the model of the driver's preprocessor. Expansion
// is checked through `#if`: a case holds when `#if <expansion> == <value>`
// reaches its `#error`. The C17 6.10.3 rules each get a case, then the
// conditionals, the budgets and the expression depth.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "preprocess/macro_engine.h"

namespace ms {
namespace {

const std::vector<std::string> kFiles = {"root.frag", "map.glsl"};

// Feeds `text` as file 1 (map.glsl); returns the error message, or "" when none.
std::string run(const std::string& text, PreprocessLimits limits = {}) {
  MacroEngine e(limits, kFiles);
  try {
    e.begin_file();
    int n = 0;
    size_t pos = 0;
    while (pos <= text.size()) {
      const size_t nl = text.find('\n', pos);
      const size_t end = nl == std::string::npos ? text.size() : nl;
      e.line(std::string_view(text).substr(pos, end - pos), {1, ++n});
      pos = end + 1;
    }
    e.end_file();
    e.finish();
  } catch (const Error& err) {
    return err.what();
  }
  return "";
}

// True when the condition holds after `defs`.
bool holds(const std::string& defs, const std::string& condition) {
  const std::string err = run(defs + "\n#if " + condition + "\n#error yes\n#endif\n");
  EXPECT_TRUE(err.empty() || err.find("#error yes") != std::string::npos) << condition << ": " << err;
  return err.find("#error yes") != std::string::npos;
}

TEST(MacroEngine, ObjectLikeMacrosAreTextNotValues) {
  EXPECT_TRUE(holds("#define A 1+2", "A*3 == 7"));
  EXPECT_FALSE(holds("#define A 1+2", "A*3 == 9"));
  EXPECT_TRUE(holds("#define A (1+2)", "A*3 == 9"));
}

TEST(MacroEngine, FunctionLikeArgumentsAreSubstitutedAsTokens) {
  EXPECT_TRUE(holds("#define SQ(x) x*x", "SQ(1+1) == 3"));
  EXPECT_TRUE(holds("#define ADD(a, b) ((a) + (b))", "ADD(ADD(1, 2), 4) == 7"));
  EXPECT_TRUE(holds("#define F(x) x\n#define G F", "G(5) == 5"));  // the rescan takes the call's arguments
  EXPECT_TRUE(holds("#define F(x) x", "F == 0"));                  // a name without a call stays a name
}

TEST(MacroEngine, AMacroNeverExpandsInsideItself) {
  EXPECT_TRUE(holds("#define X X+1", "X == 1"));                    // X+1 with X left: 0 + 1
  EXPECT_TRUE(holds("#define A B+1\n#define B A+1", "A == 2"));     // A -> B+1 -> A+1+1
  EXPECT_TRUE(holds("#define F(x) x+F", "F(3) == 3"));
}

TEST(MacroEngine, PastingUsesTheArgumentsUnexpanded) {
  EXPECT_TRUE(holds("#define CAT(a, b) a##b\n#define N12 5", "CAT(N, 12) == 5"));
  EXPECT_TRUE(holds("#define CAT(a, b) a##b", "CAT(1, 2) == 12"));
  EXPECT_TRUE(holds("#define CAT(a, b) a##b\n#define ONE 1\n#define ONEONE 11", "CAT(ONE, ONE) == 11"));
  EXPECT_TRUE(holds("#define CAT(a, b) a##b", "CAT(, 7) == 7 && CAT(7, ) == 7"));
  // Without ##, arguments expand first.
  EXPECT_TRUE(holds("#define ONE 1\n#define ID(x) x", "ID(ONE) == 1"));
}

TEST(MacroEngine, DefinedUndefAndBuiltins) {
  EXPECT_TRUE(holds("#define FOO", "defined(FOO) && defined FOO && !defined(BAR)"));
  EXPECT_FALSE(holds("#define FOO\n#undef FOO", "defined(FOO)"));
  EXPECT_TRUE(holds("", "UNDEFINED_NAME == 0"));  // desktop GLSL: 0, as Mesa
  EXPECT_TRUE(holds("#version 450 core", "__VERSION__ == 450 && GL_core_profile && GL_FRAGMENT_PRECISION_HIGH"));
  EXPECT_FALSE(holds("#version 450 core", "defined(GL_ES)"));
  // __LINE__ is what the driver sees: file 1, line 2 of the text fed.
  EXPECT_TRUE(holds("", "__LINE__ == 100002 && __FILE__ == 1"));
  EXPECT_TRUE(holds("#define LONG 1 + \\\n 2", "LONG == 3"));  // a continued line is one line
  EXPECT_TRUE(holds("", "0x10 == 16 && 010 == 8 && 7u == 7 && (5 ? 2 : 3) == 2 && -1 < 0 && (1 << 4) == 16"));
}

TEST(MacroEngine, OnlyTheTakenBranchCounts) {
  const std::string chain = "#if A == 1\n#error one\n#elif A == 2\n#error two\n#else\n#error other\n#endif\n";
  EXPECT_NE(run("#define A 1\n" + chain).find("#error one"), std::string::npos);
  EXPECT_NE(run("#define A 2\n" + chain).find("#error two"), std::string::npos);
  EXPECT_NE(run("#define A 3\n" + chain).find("#error other"), std::string::npos);
  EXPECT_EQ(run("#if 0\n#if 1\n#error nested in dead\n#endif\n#else\n#endif\n"), "");
  EXPECT_EQ(run("/*\n#error in a comment\n*/\n// #error too\n"), "");
  EXPECT_EQ(run("#ifdef X\n#define BOMB\n#endif\n#ifdef BOMB\n#error defined in a dead group\n#endif\n"), "");
}

TEST(MacroEngine, TheErrorNamesFileLineAndMessage) {
  const std::string err = run("float a;\n\n#error  not   supported here\n");
  EXPECT_EQ(err, "map.glsl:3: #error not supported here");
}

TEST(MacroEngine, DriverMacrosAreLeftToTheDriver) {
  // Mesa defines its extension macros; which ones is the driver's to say.
  EXPECT_EQ(run("#ifdef GL_ARB_gpu_shader_fp64\n#error no fp64\n#endif\n"), "");
  EXPECT_EQ(run("#ifndef GL_ARB_gpu_shader_fp64\n#error no fp64\n#endif\n"), "");
  EXPECT_EQ(run("#if defined(GL_EXT_foo) || 0\n#error x\n#else\n#error y\n#endif\n"), "");
  // But a branch that is dead whatever the driver says stays dead, and one
  // that is live still is.
  EXPECT_NE(run("#if 1 \n#error live\n#endif\n#ifdef GL_X\n#endif\n").find("#error live"), std::string::npos);
}

TEST(MacroEngine, MalformedConditionalsAreErrors) {
  EXPECT_NE(run("#if 1\nfloat a;\n").find("map.glsl:1: unterminated #if"), std::string::npos);
  EXPECT_NE(run("#endif\n").find("#endif without #if"), std::string::npos);
  EXPECT_NE(run("#if 1\n#else\n#else\n#endif\n").find("#else after #else"), std::string::npos);
  EXPECT_NE(run("#if 1/0\n#endif\n").find("division by zero"), std::string::npos);
  EXPECT_NE(run("#define F(a, b) a\n#if F(1)\n#endif\n").find("takes 2 arguments, given 1"), std::string::npos);
}

TEST(MacroEngine, AMacroBombStopsAtTheBudget) {
  std::string bomb = "#define A0 x\n";
  for (int i = 1; i <= 29; ++i)
    bomb += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + " A" + std::to_string(i - 1) + "\n";
  const std::string err = run(bomb + "float y = A29;\n");
  EXPECT_NE(err.find("map.glsl:31: macro expansion makes more than 1048576 tokens"), std::string::npos) << err;
  // The budget is exact: A10 makes 2 + 4 + ... + 1024 tokens, then 1024 x.
  PreprocessLimits small;
  small.max_expanded_tokens = 3070;
  EXPECT_EQ(run(bomb + "float y = A10;\n", small), "");
  small.max_expanded_tokens = 3069;
  EXPECT_NE(run(bomb + "float y = A10;\n", small), "");
  // Through function-like macros and #if alike.
  EXPECT_NE(run("#define D(x) x x\n#if D(D(D(D(D(D(D(D(D(D(D(D(D(D(D(D(D(D(D(D(1))))))))))))))))))))\n#endif\n").find(
                "macro expansion makes more than"),
            std::string::npos);
}

std::string chain(int terms, const std::string& op = " + ") {
  std::string s = "float k = a";
  for (int i = 1; i < terms; ++i) s += op + "a";
  return s + ";\n";
}

TEST(MacroEngine, ExpressionDepthIsBoundedOnTheExpandedCode) {
  PreprocessLimits l;
  l.max_expression_depth = 1000;
  EXPECT_EQ(run(chain(990), l), "");
  EXPECT_NE(run(chain(1001), l).find("map.glsl:1: expression nested more than 1000 levels deep"), std::string::npos);
  // Long lists are flat: an array of 5000 elements is shallow.
  std::string list = "float t[5000] = float[](0.0";
  for (int i = 1; i < 5000; ++i) list += ", 0.0";
  EXPECT_EQ(run(list + ");\n", l), "");
  // What a macro makes counts where it is used.
  EXPECT_NE(run("#define T4(x) x + x + x + x\n#define T16(x) T4(x) + T4(x) + T4(x) + T4(x)\n"
                "#define T256(x) T16(T16(x))\nfloat k = T256(a) + T256(a) + T256(a) + T256(a);\n",
                l)
                .find("map.glsl:4: expression nested"),
            std::string::npos);
  // Nested blocks count one level each.
  std::string blocks = "void f() ";
  for (int i = 0; i < 1200; ++i) blocks += "{ ";
  for (int i = 0; i < 1200; ++i) blocks += "} ";
  EXPECT_NE(run(blocks + "\n", l).find("expression nested"), std::string::npos);
}

}  // namespace
}  // namespace ms
