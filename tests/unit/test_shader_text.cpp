// Whole numbers read from shader inputs are range-checked before they are
// narrowed (JSON channels and ids, VS Code channel numbers, int uniforms),
// labels put into generated GLSL stay inside their comment, a -D value
// cannot join the next line, and a driver's unknown name gets a did-you-mean.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "files.h"
#include "preprocess/glsl_scan.h"
#include "preprocess/log_map.h"
#include "importers/project_json.h"
#include "shader/scene_params.h"
#include "importers/vscode.h"

namespace ms {
namespace {
namespace fs = std::filesystem;

const std::string kCode = R"(void mainImage(out vec4 o, in vec2 f) { o = vec4(0); })";

// A one-pass JSON whose Image input is `input` (a JSON object's text).
std::string with_input(const std::string& input) {
  return R"({"Shader": {"renderpass": [{"type": "image", "code": ")" + kCode + R"(", "inputs": [)" + input +
         R"(]}, {"type": "buffer", "name": "Buffer A", "code": ")" + kCode +
         R"(", "outputs": [{"id": 257, "channel": 0}]}]}})";
}

std::string json_error(const std::string& text) {
  try {
    load_shadertoy_json(text, "x.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    return e.info().what;
  }
  return "no error";
}

TEST(WholeNumbers, AJsonChannelPastIntIsOutOfRangeNotWrapped) {
  // 2^32 + 1 read as an int is 1: iChannel1.
  EXPECT_NE(json_error(with_input(R"({"id": 257, "ctype": "buffer", "channel": 4294967297})"))
                .find("channel 4294967297 is out of range"),
            std::string::npos);
  EXPECT_NE(json_error(with_input(R"({"id": 257, "ctype": "buffer", "channel": -4294967295})"))
                .find("channel -4294967295 is out of range"),
            std::string::npos);
  EXPECT_NE(json_error(with_input(R"({"id": 257, "ctype": "buffer", "channel": 18446744073709551615})")),
            "no error");
  EXPECT_NE(json_error(with_input(R"({"id": 257, "ctype": "buffer", "channel": "4294967297"})"))
                .find("channel 4294967297 is out of range"),
            std::string::npos);
  // In range, as a number or the site's string, it still binds.
  const ShaderProject p = load_shadertoy_json(with_input(R"({"id": 257, "ctype": "buffer", "channel": "2"})"), "x");
  EXPECT_EQ(p.passes.back().inputs[2].kind, InputKind::buffer);
}

TEST(WholeNumbers, ABufferIdPastIntNamesNoBuffer) {
  // 4294967553 = 2^32 + 257: Buffer A once narrowed.
  EXPECT_NE(json_error(with_input(R"({"id": 4294967553, "ctype": "buffer", "channel": 0})"))
                .find("names no buffer A..D"),
            std::string::npos);
  const std::string out = R"({"Shader": {"renderpass": [{"type": "image", "code": ")" + kCode +
                          R"("}, {"type": "buffer", "name": "Mine", "code": ")" + kCode +
                          R"(", "outputs": [{"id": 4294967554, "channel": 0}]}]}})";
  EXPECT_NE(json_error(out).find("Mine writes no buffer A..D"), std::string::npos) << json_error(out);
  // 2^32 + 41 is not Cube A: a cubemap without a src.
  EXPECT_NE(json_error(with_input(R"({"id": 4294967337, "ctype": "cubemap", "channel": 0})"))
                .find("a cubemap input without a src"),
            std::string::npos);
}

struct Dir {
  test::TempDir tmp;
  const fs::path path = tmp.path();
  ShaderProject load(const std::string& text) const {
    std::ofstream(path / "main.glsl", std::ios::binary) << text;
    return load_vscode(text, path / "main.glsl", {path});
  }
  std::string error(const std::string& text) const {
    try {
      load(text);
    } catch (const Error& e) {
      return e.info().what;
    }
    return "no error";
  }
};

TEST(WholeNumbers, VsCodeChannelNumbersReadAsTheExtensionsParseInt) {
  Dir d;
  const std::string image = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";
  // Leading zeros: "00003" is 3 (parseInt), not the first three digits' 0.
  ShaderProject p = d.load("#iChannel00003 \"self\"\n" + image);
  EXPECT_EQ(p.passes.front().inputs[0].kind, InputKind::none);
  EXPECT_EQ(p.passes.front().inputs[3].kind, InputKind::buffer);
  p = d.load("#iChannel0000000000000000000001 \"self\"\n" + image);
  EXPECT_EQ(p.passes.front().inputs[1].kind, InputKind::buffer);
  // Past 3, however it is spelled, it is refused.
  EXPECT_NE(d.error("#iChannel0004 \"self\"\n" + image).find("binds iChannel0..iChannel3"), std::string::npos);
  EXPECT_NE(d.error("#iChannel1000 \"self\"\n" + image).find("binds iChannel0..iChannel3"), std::string::npos);
  EXPECT_NE(d.error("#iChannel4294967296 \"self\"\n" + image).find("binds iChannel0..iChannel3"), std::string::npos);
}

ErrorInfo uniform_error(const std::string& decl, const UniformValue& v) {
  std::string glsl = decl;
  try {
    set_uniform_defaults(glsl, {v});
  } catch (const Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for " << v.values[0];
  return {};
}

TEST(WholeNumbers, AnIntUniformTakesOnlyWhatAnIntHolds) {
  const std::string decl = "uniform int uN = 1; // range(-1e12, 1e12)\n";
  for (double v : {2147483648.0, 1e11, -2147483649.0}) {
    const ErrorInfo e = uniform_error(decl, {"uN", {v}});
    EXPECT_EQ(e.code, Exit::bad_input);
    EXPECT_NE(e.what.find("is out of range for int (-2147483648..2147483647)"), std::string::npos) << e.what;
  }
  // Whole and in range, however written: 1e3 is 1000.
  std::string glsl = decl;
  set_uniform_defaults(glsl, {{"uN", {1e3}}});
  EXPECT_NE(glsl.find("uniform int uN = 1000;"), std::string::npos) << glsl;
  glsl = decl;
  set_uniform_defaults(glsl, {{"uN", {-2147483648.0}}});
  EXPECT_NE(glsl.find("uniform int uN = -2147483648;"), std::string::npos) << glsl;
}

TEST(WholeNumbers, AFloatAtItsRangesBoundIsInside) {
  // range(0, 1e11)'s bound is the float 1e11 (99999997952): 1e11 is that float.
  std::string glsl = "uniform float uF = 1.0; // range(0, 1e11)\n";
  set_uniform_defaults(glsl, {{"uF", {1e11}}});
  EXPECT_NE(glsl.find("uniform float uF = 1e+11;"), std::string::npos) << glsl;
  const ErrorInfo e = uniform_error("uniform float uF = 1.0; // range(0, 1e11)\n", {"uF", {2e11}});
  EXPECT_NE(e.what.find("outside the range"), std::string::npos) << e.what;
}

TEST(WholeNumbers, AVsCodeIntUniformPastIntIsRefused) {
  const auto error = [](const std::string& args) -> std::string {
    try {
      vscode_uniform_line(args, "x.glsl", 3);
    } catch (const Error& e) {
      return e.info().what;
    }
    return "no error";
  };
  EXPECT_NE(error(" int n = 3000000000").find("3e+09 is out of range for int (-2147483648..2147483647)"),
            std::string::npos)
      << error(" int n = 3000000000");
  EXPECT_NE(error(" int n = 1 in { 0, 1e11 }").find("out of range for int"), std::string::npos);
  EXPECT_EQ(vscode_uniform_line(" int n = 1e3", "x.glsl", 3), "uniform int n = 1000;");
}

TEST(GeneratedText, ALabelStaysInsideItsComment) {
  EXPECT_EQ(comment_label("plain name"), "plain name");
  EXPECT_EQ(comment_label("a\nb\r\tc"), "a b  c");
  EXPECT_EQ(comment_label("x */ y"), "x * / y");
  EXPECT_EQ(comment_label("end\\"), "end/");
  EXPECT_EQ(comment_label("*\\"), "* /");  // a backslash after '*' makes no "*/" either
  const std::string line = "// pass " + comment_label("evil\n#error boom") + "\n";
  EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1);
}

TEST(GeneratedText, ADefineValueIsOneLineWithNoContinuation) {
  EXPECT_EQ(define_value_problem("1.0"), "");
  EXPECT_EQ(define_value_problem("a \\ b"), "");
  EXPECT_NE(define_value_problem("1.0\\"), "");
  EXPECT_NE(define_value_problem("1.0\\ \t"), "");
  EXPECT_EQ(define_value_problem("1\n2"), "spans lines");
}

TEST(GeneratedText, TheReturnTypeOfADefinition) {
  EXPECT_EQ(definition_type("float map(vec3 p) { return 1.0; }", "map"), "float");
  EXPECT_EQ(definition_type("vec2 other(vec3 p);\nvec4  map (vec3 p) {}", "map"), "vec4");
  EXPECT_EQ(definition_type("float d = map(p);", "map"), "");
  EXPECT_EQ(definition_type("float mapX(vec3 p) {}", "map"), "");
}

TEST(CompileLog, ATrailingNulIsNoDiagnostic) {
  ShaderSource src;
  src.files = {"root.frag"};
  // GL's INFO_LOG_LENGTH counts the terminator: a log read whole ends in it.
  const std::string log = std::string("0:3(5): error: `x' undeclared\n") + '\0';
  EXPECT_EQ(parse_info_log(log, src).size(), 1u);
}

TEST(CompileLog, AnUnknownNameGetsTheNearestDefinedOne) {
  ShaderSource src;
  src.files = {"root.frag"};
  const std::string program =
      "#define MAT_FLOOR 0\n#define MAT_BALL 1\n"
      "float sdSphere(vec3 p, float r) { return length(p) - r; }\n"
      "vec2 map(vec3 p) { return vec2(sdSphere(p, 1.0), MAT_BAL); }\n";
  std::vector<ShaderDiagnostic> d = parse_info_log(
      "0:4(40): error: `MAT_BAL' undeclared\n"
      "0:4(20): error: no function with name 'sdSpher'\n"
      "0:4(20): error: no function with name 'lenght'\n"
      "0:4(20): error: `zzzzzz' undeclared\n"
      "0:4(1): error: type mismatch\n",
      src);
  suggest_names(d, program);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0].suggestion, "did you mean 'MAT_BALL'?");
  EXPECT_EQ(d[1].suggestion, "did you mean 'sdSphere'?");
  EXPECT_EQ(d[2].suggestion, "did you mean 'length'?");
  EXPECT_EQ(d[3].suggestion, "");
  EXPECT_EQ(d[4].suggestion, "");
  EXPECT_NE(format_diagnostics(d).find("root.frag:4: error: `MAT_BAL' undeclared (did you mean 'MAT_BALL'?)\n"),
            std::string::npos)
      << format_diagnostics(d);
  // glslang's spelling too.
  std::vector<ShaderDiagnostic> g = parse_info_log("ERROR: 0:4: 'MAT_BAL' : undeclared identifier\n", src);
  suggest_names(g, program);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].suggestion, "did you mean 'MAT_BALL'?");
}

}  // namespace
}  // namespace ms
