// A broken glslViewer (or Shadertoy) file's compiler log, as `render -v`
// prints it and the viewer shows it, speaks of the user's names only: the
// wrapper's own (msFragCoord for gl_FragCoord, ...) never reach it.
#include <gtest/gtest.h>

#include <regex>

#include "run.h"

namespace ms::test {
namespace {

// gl_FragCoord read in a function of the user's, then an error.
constexpr const char* kBrokenGlslViewer =
    "uniform vec2 u_resolution;\n"
    "vec2 uv() { return gl_FragCoord.xy / u_resolution; }\n"
    "void main() {\n"
    "  gl_FragColor = vec4(uv(), undeclaredThing, 1.0);\n"
    "}\n";

constexpr const char* kBrokenShadertoy =
    "vec2 uv() { return gl_FragCoord.xy / iResolution.xy; }\n"
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  c = vec4(uv(), undeclaredThing, 1.0);\n"
    "}\n";

void expect_user_names_only(const std::string& name, const char* text) {
  TempDir dir;
  write_file(dir / name, text);
  // An empty shader cache: Mesa's would skip the compile and its log.
  const RunResult r = run_marchstudio({"render", (dir / name).string(), "--size", "8x8", "-v", "-o",
                                       (dir / "out.png").string()},
                                      {}, "export MESA_SHADER_CACHE_DIR=" + (dir / "mesa").string() + "; ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("undeclaredThing"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(name + ":"), std::string::npos) << r.err;
  std::smatch m;
  EXPECT_FALSE(std::regex_search(r.err, m, std::regex(R"(\bms[A-Z]\w*)"))) << "internal name " << m.str() << " in:\n"
                                                                            << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(GlslViewerLog, ABrokenGlslViewerFileNamesNoInternalName) { expect_user_names_only("broken.frag", kBrokenGlslViewer); }

TEST(GlslViewerLog, ABrokenShadertoyShaderNamesNoInternalName) { expect_user_names_only("broken.glsl", kBrokenShadertoy); }

}  // namespace
}  // namespace ms::test
