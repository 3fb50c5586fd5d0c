// Compile diagnostics through the real binary: "+N more" counts only what
// -v prints, view and test take -v, a map() of the wrong type says so, and
// an unknown name gets a did-you-mean. Also generated GLSL: labels stay in
// their comments, a -D value cannot join the next line, and an int uniform
// past int's range is refused.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "run.h"
#include "shadertoy_json.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// Compile outcomes must not come from an earlier run's disk cache.
std::string fresh_cache(const TempDir& dir) { return "MESA_SHADER_CACHE_DIR='" + (dir / "cache").string() + "' "; }

// seed.toml beside a map file of our own.
void seed_with_map(const TempDir& dir, const std::string& map) {
  write_file(dir / "seed.toml", read_file(source_dir() / "scenes/seed.toml"));
  write_file(dir / "seed.glsl", map);
}

int lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  for (size_t at = 0; at < text.size();) {
    const size_t end = std::min(text.find('\n', at), text.size());
    if (text.compare(at, prefix.size(), prefix) == 0) ++n;
    at = end + 1;
  }
  return n;
}

TEST(CompileDiagnostics, MoreCountsOnlyTheErrorsMinusVPrints) {
  TempDir dir;
  write_file(dir / "bad.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(nope_a) + nope_b; }\n");
  const RunResult quiet = run_marchstudio({"render", "bad.glsl", "-o", "x.png"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(quiet.exit_code, 2);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(quiet.err, m, std::regex(R"(\+(\d+) more; -v prints them all)"))) << quiet.err;
  const RunResult loud = run_marchstudio({"render", "bad.glsl", "-o", "x.png", "-v"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(lines_starting(loud.err, "bad.glsl:1: error: "), std::stoi(m[1]) + 1) << quiet.err << loud.err;
  // One error is one error: no "+1 more" for the log's terminator.
  write_file(dir / "one.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); float x = nope; }\n");
  const RunResult one = run_marchstudio({"render", "one.glsl", "-o", "x.png"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(one.exit_code, 2);
  EXPECT_NE(one.err.find("one.glsl:1: shader compile error: `nope' undeclared"), std::string::npos) << one.err;
  EXPECT_EQ(one.err.find("more"), std::string::npos) << one.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(CompileDiagnostics, ViewAndTestTakeMinusV) {
  TempDir dir;
  write_file(dir / "bad.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(nope_a) + nope_b; }\n");
  write_file(dir / "s.toml", "[[case]]\nname = \"bad\"\nshader = \"bad.glsl\"\nreference = \"bad.png\"\nsize = [16, 9]\n");
  const RunResult quiet = run_marchstudio({"test", "s.toml"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(quiet.exit_code, 2) << quiet.err;
  EXPECT_NE(quiet.out.find("more; -v prints them all"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("nope_b"), std::string::npos) << quiet.out;
  const RunResult loud = run_marchstudio({"test", "s.toml", "-v"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(loud.exit_code, 2) << loud.err;
  EXPECT_NE(loud.out.find("  bad.glsl:1: error: `nope_b' undeclared\n"), std::string::npos) << loud.out;
  // view parses -v as render does (here the missing file is what is wrong).
  const RunResult view = run_marchstudio({"view", "-v", "none.toml"}, dir.path());
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_NE(view.err.find("none.toml: scene file not found"), std::string::npos) << view.err;
  EXPECT_EQ(view.err.find("-v"), std::string::npos) << view.err;
}

TEST(CompileDiagnostics, AMapOfTheWrongTypeSaysWhatItReturns) {
  TempDir dir;
  seed_with_map(dir, "float map(vec3 p) {\n  return length(p) - 1.0;\n}\n");
  const RunResult r = run_marchstudio({"render", "seed.toml", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("seed.toml: scene.map: map() returns float; it must return vec2 (distance, material id)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(CompileDiagnostics, AnUnknownNameGetsADidYouMean) {
  TempDir dir;
  seed_with_map(dir, "vec2 map(vec3 p) {\n  return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_BAL);\n}\n");
  RunResult r = run_marchstudio({"render", "seed.toml", "-o", "x.png", "--size", "16x9"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("seed.glsl:2: shader compile error: `MAT_BAL' undeclared (did you mean 'MAT_BALL'?"),
            std::string::npos)
      << r.err;
  // A library function, misspelled; -v says it on the diagnostic's own line.
  seed_with_map(dir, "vec2 map(vec3 p) {\n  return vec2(sdSpher(p - vec3(0.0, 1.0, 0.0), 1.0), MAT_BALL);\n}\n");
  r = run_marchstudio({"render", "seed.toml", "-o", "x.png", "--size", "16x9", "-v"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("seed.glsl:2: error: no function with name 'sdSpher' (did you mean 'sdSphere'?)\n"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(GeneratedGlsl, LabelsWithNewlinesStayInTheirComments) {
  TempDir dir;
  std::string scene = read_file(source_dir() / "scenes/seed.toml");
  const std::string name = "name = \"seed\"";
  ASSERT_NE(scene.find(name), std::string::npos);
  scene.replace(scene.find(name), name.size(), "name = \"seed\\n#error from the name */\"");
  write_file(dir / "seed.toml", scene);
  write_file(dir / "seed.glsl", read_file(source_dir() / "scenes/seed.glsl"));
  RunResult r = run_marchstudio({"render", "seed.toml", "--print-shader"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines_starting(r.out, "#error from the name"), 0);
  EXPECT_NE(r.out.find("// generated by marchstudio for scene 'seed #error from the name * /'\n"), std::string::npos);
  r = run_marchstudio({"render", "seed.toml", "--size", "16x9", "-o", "x.png"}, dir.path(), fresh_cache(dir));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // A pass name in the multi-pass --print-shader's headers.
  const std::string code = "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }";
  write_file(dir / "two.json",
             shader({pass("Buffer A\\n#error from the pass", "buffer", 257, code),
                     pass("Image", "image", 0, "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }",
                          buffer_input(0, 257))}));
  r = run_marchstudio({"render", "two.json", "--print-shader"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines_starting(r.out, "#error"), 0) << r.out.substr(0, 400);
  EXPECT_NE(r.out.find("// ==== marchstudio: pass Buffer A #error from the pass ====\n"), std::string::npos);
}

TEST(GeneratedGlsl, ADefineEndingInABackslashIsRefused) {
  TempDir dir;
  write_file(dir / "ok.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }\n");
  const RunResult r = run_marchstudio({"render", "ok.glsl", "-D", "K=1.0\\", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("-D: the value of 'K' ends in a backslash"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(GeneratedGlsl, AnIntUniformPastIntIsRefused) {
  TempDir dir;
  write_file(dir / "u.glsl",
             "uniform int uN = 1; // range(0, 1e12)\n"
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(float(uN) * 0.0); }\n");
  for (const char* v : {"uN=2147483648", "uN=1e11"}) {
    const RunResult r = run_marchstudio({"render", "u.glsl", "--size", "8x8", "-o", "x.png", "--uniform", v}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << v;
    EXPECT_NE(r.err.find("--uniform uN: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is out of range for int (-2147483648..2147483647)"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
  }
  const RunResult ok = run_marchstudio({"render", "u.glsl", "--size", "8x8", "-o", "x.png", "--uniform", "uN=1e3"},
                                       dir.path(), fresh_cache(dir));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

}  // namespace
}  // namespace ms::test
