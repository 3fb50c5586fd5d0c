// preprocess(): includes, #pragma once, search order, cycles, missing files,
// #version placement, display paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "core/error.h"
#include "preprocess/preprocess.h"
#include "test_shader_util.h"

namespace ms {
namespace {

namespace fs = std::filesystem;
using test::shader_data;

// Runs preprocess and returns the thrown error; fails the test when none is.
ErrorInfo preprocess_error(const std::string& root, const fs::path& dir, const PreprocessOptions& opts = {}) {
  try {
    preprocess(root, "root.frag", dir, opts);
  } catch (const Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "expected an ms::Error";
  return {};
}

size_t count_of(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
  return n;
}

TEST(ShaderPreprocess, NestedIncludesThreeLevels) {
  const fs::path dir = shader_data("nested");
  ShaderSource s = preprocess("#version 450 core\n#include \"a.glsl\"\nvoid main() {}\n", "root.frag", dir, {});
  const std::string expected =
      "#version 450 core\n"
      "#line 100001 1\n"
      "// a.glsl: level 1\n"
      "float a_value() { return 1.0; }\n"
      "#line 200001 2\n"
      "// b.glsl: level 2, includes c.glsl from its own directory\n"
      "#line 300001 3\n"
      "// c.glsl: level 3\n"
      "float c_value() { return 3.0; }\n"
      "#line 200003 2\n"
      "float b_value() { return c_value() * 2.0; }\n"
      "#line 100004 1\n"
      "float a_after() { return 2.0; }\n"
      "#line 3 0\n"
      "void main() {}\n";
  // Line L of file N is numbered N*kLineStride+L (Mesa drops the string number).
  static_assert(kLineStride == 100000);
  EXPECT_EQ(s.text, expected);
  ASSERT_EQ(s.files.size(), 4u);
  EXPECT_EQ(s.files[0], "root.frag");
  EXPECT_EQ(s.files[1], display_path(dir / "a.glsl"));
  EXPECT_EQ(s.files[3], display_path(dir / "sub/c.glsl"));
  const std::vector<fs::path> deps = {fs::canonical(dir / "a.glsl"), fs::canonical(dir / "sub/b.glsl"),
                                      fs::canonical(dir / "sub/c.glsl")};
  EXPECT_EQ(s.dependencies, deps);
}

TEST(ShaderPreprocess, PragmaOnceIncludesAFileOnce) {
  const fs::path dir = shader_data("once");
  ShaderSource s = preprocess(
      "#include \"lib.glsl\"\n#include \"user.glsl\"\n#include \"lib.glsl\"\n"
      "#include \"plain.glsl\"\n#include \"plain.glsl\"\n",
      "root.frag", dir, {});
  EXPECT_EQ(count_of(s.text, "float once_lib()"), 1u);
  EXPECT_EQ(count_of(s.text, "float once_user()"), 1u);
  // No #pragma once: included every time, but numbered as one source string.
  EXPECT_EQ(count_of(s.text, "float plain_counter_decl;"), 2u);
  EXPECT_EQ(s.files.size(), 4u);  // root, lib, user, plain
  EXPECT_EQ(s.dependencies.size(), 3u);
  // The directive itself never reaches the driver (glslang warns about it).
  EXPECT_EQ(s.text.find("\n#pragma once"), std::string::npos);
}

TEST(ShaderPreprocess, IncluderDirectoryThenIncludeDirsInOrder) {
  const fs::path base = shader_data("order");
  PreprocessOptions opts{{base / "inc", base / "inc2"}};
  ShaderSource s = preprocess("#include \"x.glsl\"\n#include <x.glsl>\n#include \"only.glsl\"\n"
                              "#include \"z.glsl\"\n#include \"w.glsl\"\n",
                              "root.frag", base / "dir_a", opts);
  EXPECT_NE(s.text.find("// x from the includer's directory"), std::string::npos);
  EXPECT_NE(s.text.find("// x from include dir 1"), std::string::npos);  // <x.glsl> skips the includer's dir
  // only.glsl's own "y.glsl" resolves next to only.glsl, not next to the root.
  EXPECT_NE(s.text.find("// y next to only.glsl in include dir 1"), std::string::npos);
  EXPECT_EQ(s.text.find("// y from the root's directory"), std::string::npos);
  EXPECT_NE(s.text.find("// z from include dir 1"), std::string::npos);
  EXPECT_EQ(s.text.find("// z from include dir 2"), std::string::npos);
  EXPECT_NE(s.text.find("// w only in include dir 2"), std::string::npos);
}

TEST(ShaderPreprocess, AbsoluteIncludePath) {
  const fs::path abs = fs::absolute(shader_data("order/inc2/w.glsl"));
  ShaderSource s = preprocess("#include \"" + abs.generic_string() + "\"\n", "root.frag", "/nonexistent", {});
  EXPECT_NE(s.text.find("// w only in include dir 2"), std::string::npos);
}

TEST(ShaderPreprocess, TwoFileCycleNamesFileAndLine) {
  const fs::path dir = shader_data("cycle2");
  ErrorInfo e = preprocess_error("#include \"a.glsl\"\n", dir);
  EXPECT_EQ(e.code, Exit::bad_input);
  EXPECT_EQ(e.file, display_path(dir / "b.glsl"));
  EXPECT_EQ(e.line, 3);
  EXPECT_TRUE(e.key.empty());
  const std::string a = display_path(dir / "a.glsl"), b = display_path(dir / "b.glsl");
  EXPECT_EQ(e.what, "include cycle: " + a + " -> " + b + " -> " + a);
}

TEST(ShaderPreprocess, ThreeFileCycleNamesFileAndLine) {
  const fs::path dir = shader_data("cycle3");
  ErrorInfo e = preprocess_error("// root\n#include \"b.glsl\"\n", dir);
  EXPECT_EQ(e.file, display_path(dir / "a.glsl"));
  EXPECT_EQ(e.line, 1);
  // Entered at b: the chain starts where the cycle starts.
  EXPECT_TRUE(std::regex_search(e.what, std::regex("^include cycle: \\S*b\\.glsl -> \\S*c\\.glsl -> "
                                                   "\\S*a\\.glsl -> \\S*b\\.glsl$")))
      << e.what;
}

TEST(ShaderPreprocess, SelfIncludeIsACycle) {
  const fs::path dir = shader_data("cycle1");
  ErrorInfo e = preprocess_error("#include \"self.glsl\"\n", dir);
  EXPECT_EQ(e.file, display_path(dir / "self.glsl"));
  EXPECT_EQ(e.line, 2);
  EXPECT_NE(e.what.find("include cycle"), std::string::npos);
}

TEST(ShaderPreprocess, MissingIncludeInRootNamesSearchedDirs) {
  const fs::path base = shader_data("order");
  ErrorInfo e = preprocess_error("#version 450 core\n#include \"nope.glsl\"\n", base / "dir_a",
                                 PreprocessOptions{{base / "inc"}});
  EXPECT_EQ(e.file, "root.frag");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.what, "cannot find include 'nope.glsl'");
  EXPECT_NE(e.hint.find(display_path(base / "dir_a")), std::string::npos) << e.hint;
  EXPECT_NE(e.hint.find(display_path(base / "inc")), std::string::npos) << e.hint;
}

TEST(ShaderPreprocess, MissingIncludeInLibraryFile) {
  const fs::path dir = shader_data("version_lib");
  ErrorInfo e = preprocess_error("#include \"missing_inside.glsl\"\n", dir);
  EXPECT_EQ(e.file, display_path(dir / "missing_inside.glsl"));
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.what, "cannot find include 'not_there.glsl'");
}

TEST(ShaderPreprocess, VersionInIncludedFileIsAnError) {
  const fs::path dir = shader_data("version_lib");
  ErrorInfo e = preprocess_error("#version 450 core\n#include \"lib.glsl\"\n", dir);
  EXPECT_EQ(e.file, display_path(dir / "lib.glsl"));
  EXPECT_EQ(e.line, 2);
  EXPECT_NE(e.what.find("#version"), std::string::npos);
}

TEST(ShaderPreprocess, RootVersionStaysFirstAndMustComeFirst) {
  ShaderSource s = preprocess("// header comment\n#version 450 core\n#include \"a.glsl\"\n", "root.frag",
                              shader_data("nested"), {});
  EXPECT_EQ(s.text.rfind("// header comment\n#version 450 core\n#line 100001 1\n", 0), 0u);
  ErrorInfo e = preprocess_error("float x;\n#version 450 core\n", shader_data("nested"));
  EXPECT_EQ(e.line, 2);
}

TEST(ShaderPreprocess, IncludesInBlockCommentsAreIgnored) {
  ShaderSource s = preprocess("/* old:\n#include \"nope.glsl\"\n*/ float a; /* one-line */\n"
                              "// #include \"nope.glsl\"\n#include \"a.glsl\"\n",
                              "root.frag", shader_data("nested"), {});
  EXPECT_NE(s.text.find("#include \"nope.glsl\""), std::string::npos);  // kept verbatim, not expanded
  EXPECT_NE(s.text.find("float a_value()"), std::string::npos);
  EXPECT_EQ(preprocess_error("/* never closed\n", shader_data("nested")).what, "unterminated /* comment");
}

TEST(ShaderPreprocess, MalformedIncludeLines) {
  const fs::path dir = shader_data("nested");
  EXPECT_EQ(preprocess_error("#include a.glsl\n", dir).line, 1);
  EXPECT_EQ(preprocess_error("\n#include \"a.glsl\n", dir).line, 2);
  EXPECT_NE(preprocess_error("#include \"a.glsl\" junk\n", dir).what.find("junk"), std::string::npos);
  // A trailing line comment is fine, and CRLF line ends are accepted.
  EXPECT_NO_THROW(preprocess("#include \"a.glsl\" // why\r\n", "root.frag", dir, {}));
}

TEST(ShaderPreprocess, DisplayPathIsRelativeUnderCwdElseAbsolute) {
  const fs::path cwd = fs::current_path();
  EXPECT_EQ(display_path(cwd / "sub" / "f.glsl"), "sub/f.glsl");
  const fs::path outside = fs::weakly_canonical(cwd.parent_path()) / "zz_not_under_cwd.glsl";
  if (cwd.has_parent_path() && cwd != cwd.root_path())
    EXPECT_EQ(display_path(outside), outside.generic_string());
  EXPECT_EQ(display_path(""), "");
}

}  // namespace
}  // namespace ms
