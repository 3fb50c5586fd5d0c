// A glslViewer user's command line (cli/glslviewer_flags.h): -w, -h N, -E
// and --headless are refused in one line naming --size and -o (exit 2,
// never help with exit 0 and no image), an image given as an input names
// --texture instead of failing as a batch job, and --mouse X,Y sets u_mouse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const fs::path kRipple = source_dir() / "docs/examples/glslviewer/ripple.frag";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(GlslViewerHabits, SizeAndExportFlagsNameWhatToUse) {
  TempDir dir;
  const std::string out = (dir / "out.png").string();
  RunResult r = run_marchstudio({"render", kRipple.string(), "-w", "320", "-h", "180", "-E", out});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("glslViewer"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--size 320x180"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("-o " + out), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "not the help: " << r.out;
  EXPECT_FALSE(fs::exists(out));
  // -h with a height alone, and --headless.
  r = run_marchstudio({"render", kRipple.string(), "-h", "180", "-o", out});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--size Wx180"), std::string::npos) << r.err;
  r = run_marchstudio({"render", kRipple.string(), "--headless", "-o", out});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--headless"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // -h alone is help, as before.
  r = run_marchstudio({"render", "-h"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("--output-dir"), std::string::npos) << r.out;
}

TEST(GlslViewerHabits, AnImageInputNamesTexture) {
  TempDir dir;
  const RunResult seed = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "--size", "16x9",
                                          "-o", (dir / "tex.png").string()});
  ASSERT_EQ(seed.exit_code, 0) << seed.err;
  for (const bool with_o : {true, false}) {
    std::vector<std::string> args = {"render", kRipple.string(), (dir / "tex.png").string(), "--size", "32x18"};
    if (with_o) args.insert(args.end(), {"-o", (dir / "out.png").string()});
    else args.insert(args.end(), {"--output-dir", (dir / "batch").string()});
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("tex.png: an image"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--texture"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("jobs failed"), std::string::npos) << "not a failed batch job: " << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    EXPECT_FALSE(fs::exists(dir / "batch"));
  }
  // view refuses it the same way, before any window (no display is needed).
  const RunResult v = run_marchstudio({"view", (dir / "tex.png").string()});
  EXPECT_EQ(v.exit_code, 2) << v.err;
  EXPECT_EQ(lines(v.err), 1) << v.err;
  EXPECT_NE(v.err.find("tex.png: an image"), std::string::npos) << v.err;
  EXPECT_NE(v.err.find("--texture"), std::string::npos) << v.err;
}

TEST(GlslViewerHabits, MouseXYSetsUMouse) {
  TempDir dir;
  write_file(dir / "m.frag",
             "uniform vec2 u_mouse;\n"
             "void main() { gl_FragColor = vec4(u_mouse.x / 255.0, u_mouse.y / 255.0, 0.0, 1.0); }\n");
  RunResult r = run_marchstudio({"render", (dir / "m.frag").string(), "--size", "2x2", "--mouse", "100,50", "-o",
                                 (dir / "a.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "a.png");
  EXPECT_NEAR(img.at(0, 0, 0), 100.0f / 255.0f, 0.5f / 255.0f);
  EXPECT_NEAR(img.at(0, 0, 1), 50.0f / 255.0f, 0.5f / 255.0f);
  // Three numbers are neither form.
  r = run_marchstudio({"render", (dir / "m.frag").string(), "--size", "2x2", "--mouse", "1,2,3", "-o",
                       (dir / "b.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("X,Y"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
