// Every kind of bad input: one line on stderr naming file, line and key,
// exit code 2, and no output file (nor a temporary) left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>

#include "run.h"

namespace ms::test {
namespace {

const char* kMap = "vec2 map(vec3 p) { return vec2(length(p - vec3(0.0, 1.0, 0.0)) - 1.0, MAT_GROUND); }\n";

std::string scene_text(const std::string& extra_render = "", const std::string& tail = "") {
  return "[scene]\nmap = \"m.glsl\"\n\n[render]\nwidth = 32\nheight = 18\n" + extra_render +
         "\n[[materials]]\nname = \"ground\"\n" + tail;
}

struct BadInput : ::testing::Test {
  TempDir dir;
  void SetUp() override { write_file(dir / "m.glsl", kMap); }

  // Runs render with the scene text, returns the result; asserts the common contract.
  RunResult render_expecting_error(const std::vector<std::string>& args) {
    RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_EQ(r.err.rfind("marchstudio: ", 0), 0u) << r.err;
    auto names = dir.entries();
    for (const auto& n : names)
      EXPECT_TRUE(n == "m.glsl" || n == "s.toml" || n == "a.glsl" || n == "b.glsl" || n == "sub")
          << "left behind: " << n;
    return r;
  }
};

TEST_F(BadInput, MissingSceneFile) {
  auto r = render_expecting_error({"render", "nope.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("nope.toml"), std::string::npos) << r.err;
}

TEST_F(BadInput, MissingMapFile) {
  write_file(dir / "s.toml", "[scene]\nmap = \"missing.glsl\"\n[[materials]]\nname = \"ground\"\n");
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("s.toml:2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("missing.glsl"), std::string::npos) << r.err;
}

TEST_F(BadInput, MalformedToml) {
  write_file(dir / "s.toml", "[scene]\nmap = \"m.glsl\"\n[render\nwidth = 3\n");
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("s.toml:3"), std::string::npos) << r.err;
}

TEST_F(BadInput, UnknownKeyWithSuggestion) {
  write_file(dir / "s.toml", scene_text("spq = 4\n"));
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("s.toml:7"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("render.spq"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'spp'"), std::string::npos) << r.err;
}

TEST_F(BadInput, WrongType) {
  write_file(dir / "s.toml", scene_text("spp = \"many\"\n"));
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("s.toml:7"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("render.spp"), std::string::npos) << r.err;
}

TEST_F(BadInput, NanAndInfInScene) {
  write_file(dir / "s.toml", scene_text("exposure = nan\n"));
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("s.toml:7"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("render.exposure"), std::string::npos) << r.err;
  write_file(dir / "s.toml", scene_text("", "color = [1.0, inf, 0.0]\n"));
  r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("s.toml:10"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("materials[0].color"), std::string::npos) << r.err;
}

TEST_F(BadInput, NanOnTheCommandLine) {
  write_file(dir / "s.toml", scene_text());
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png", "--time", "nan"});
  EXPECT_NE(r.err.find("--time"), std::string::npos) << r.err;
}

TEST_F(BadInput, ShaderCompileErrorNamesTheGlslLine) {
  write_file(dir / "m.glsl", "// a comment\nvec2 map(vec3 p) {\n  return vec2(length(p) - 1.0, MAT_GROUND)\n}\n");
  write_file(dir / "s.toml", scene_text());
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  // The missing ';' is reported on line 3 or 4 depending on the driver's parser.
  EXPECT_TRUE(r.err.find("m.glsl:3:") != std::string::npos || r.err.find("m.glsl:4:") != std::string::npos)
      << r.err;
}

TEST_F(BadInput, CompileErrorTwoIncludesDeepMapsToItsFile) {
  write_file(dir / "m.glsl", "#include \"a.glsl\"\nvec2 map(vec3 p) { return vec2(helper(p), MAT_GROUND); }\n");
  write_file(dir / "a.glsl", "// level one\n#include \"b.glsl\"\nfloat helper(vec3 p) { return inner(p); }\n");
  write_file(dir / "b.glsl", "// level two\n\nfloat inner(vec3 p) { return length(p) - undefined_radius; }\n");
  write_file(dir / "s.toml", scene_text());
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("b.glsl:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("undefined_radius"), std::string::npos) << r.err;
}

TEST_F(BadInput, IncludeCycle) {
  write_file(dir / "m.glsl", "#include \"a.glsl\"\nvec2 map(vec3 p) { return vec2(length(p) - 1.0, 0.0); }\n");
  write_file(dir / "a.glsl", "// a\n#include \"b.glsl\"\n");
  write_file(dir / "b.glsl", "// b\n\n#include \"a.glsl\"\n");
  write_file(dir / "s.toml", scene_text());
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("b.glsl:3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cycle"), std::string::npos) << r.err;
}

TEST_F(BadInput, AbsurdSizes) {
  write_file(dir / "s.toml", scene_text());
  for (const char* size : {"0x10", "-5x10", "10x0", "abc", "100000x100"}) {
    auto r = render_expecting_error({"render", "s.toml", "-o", "out.png", "--size", size});
    EXPECT_NE(r.err.find("--size"), std::string::npos) << size << ": " << r.err;
  }
  std::string zero_width = scene_text();
  zero_width.replace(zero_width.find("width = 32"), 10, "width = 0");
  write_file(dir / "s.toml", zero_width);
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.png"});
  EXPECT_NE(r.err.find("render.width"), std::string::npos) << r.err;
}

TEST_F(BadInput, UnwritableOutput) {
  write_file(dir / "s.toml", scene_text());
  // A missing directory is made (mkdir -p); one under a file cannot be.
  auto r = render_expecting_error({"render", "s.toml", "-o", "m.glsl/sub/out.png"});
  EXPECT_NE(r.err.find("output directory cannot be made: m.glsl is not a directory"), std::string::npos) << r.err;
  r = render_expecting_error({"render", "s.toml", "-o", "m.glsl/out.png"});  // parent is a file
  EXPECT_NE(r.err.find("m.glsl"), std::string::npos) << r.err;
  if (geteuid() != 0) {  // root writes through permission bits
    std::filesystem::create_directory(dir / "sub");
    std::filesystem::permissions(dir / "sub", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    r = render_expecting_error({"render", "s.toml", "-o", "sub/out.png"});
    EXPECT_NE(r.err.find("not writable"), std::string::npos) << r.err;
  }
}

TEST_F(BadInput, UnknownImageExtension) {
  write_file(dir / "s.toml", scene_text());
  auto r = render_expecting_error({"render", "s.toml", "-o", "out.bmpx"});
  EXPECT_NE(r.err.find(".bmpx"), std::string::npos) << r.err;
}

TEST_F(BadInput, UnknownFlagAndBackend) {
  write_file(dir / "s.toml", scene_text());
  render_expecting_error({"render", "s.toml", "--frobnicate"});
  auto r = render_expecting_error({"render", "s.toml", "--backend", "vulkan"});
  EXPECT_NE(r.err.find("backend"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
