// Include confinement (preprocess/preprocess.h PreprocessOptions::roots,
// AssembleOptions::allow_include): an #include may only read files under
// the scene's directory and the shader library, judged on canonical paths.
// Attacks: an absolute path (/etc/passwd), "../.." out of the scene, a
// symlinked file and a symlinked directory leading out, and a map file or a
// wrapped Shadertoy shader outside the scene. Each is refused with one line
// at the including file:line that names the path and shows none of its text.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "files.h"
#include "shader/assemble.h"
#include "preprocess/preprocess.h"
#include "importers/shadertoy.h"

namespace ms {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSecret = "TOP_SECRET_do_not_echo";

void put(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// <tmp>/project/scene/ (the scene), <tmp>/project/lib/ (the library) and
// <tmp>/secret/secret.glsl beside them, outside both.
class Confine : public ::testing::Test {
 protected:
  void SetUp() override {
    tmp = fs::canonical(tmp_dir.path());
    put(secret(), std::string("// ") + kSecret + "\nfloat secret() { return 1.0; }\n");
    put(lib() / "lib.glsl", "float lib() { return 2.0; }\n");
    fs::create_directories(scene());
  }

  fs::path scene() const { return tmp / "project/scene"; }
  fs::path lib() const { return tmp / "project/lib"; }
  fs::path secret() const { return tmp / "secret/secret.glsl"; }
  PreprocessOptions confined() const {
    PreprocessOptions o;
    o.include_dirs = {lib()};
    o.roots = {scene(), lib()};
    return o;
  }
  // The error of preprocessing `root` (as scene/root.glsl), which must fail.
  ErrorInfo refused(const std::string& root) {
    try {
      ShaderSource s = preprocess(root, "root.glsl", scene(), confined());
      ADD_FAILURE() << "accepted:\n" << s.text;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Exit::bad_input);
      const std::string line = e.what();
      EXPECT_EQ(line.find('\n'), std::string::npos) << "not one line: " << line;
      EXPECT_EQ(line.find(kSecret), std::string::npos) << "shows the file's content: " << line;
      EXPECT_NE(line.find("--allow-include"), std::string::npos) << line;
      return e.info();
    }
    return {};
  }

  test::TempDir tmp_dir;
  fs::path tmp;
};

TEST_F(Confine, AbsolutePathOutsideIsRefusedWithoutReadingIt) {
  const ErrorInfo e = refused("// root\n#include \"/etc/passwd\"\n");
  EXPECT_EQ(e.file, "root.glsl");
  EXPECT_EQ(e.line, 2);
  EXPECT_NE(e.what.find("'/etc/passwd'"), std::string::npos) << e.what;
  EXPECT_NE(e.what.find("outside the directories includes may read"), std::string::npos) << e.what;
  EXPECT_EQ(e.what.find("root:"), std::string::npos) << "passwd content in: " << e.what;
  // Our own secret by absolute path: the same, and its name is given.
  const ErrorInfo s = refused("#include \"" + secret().string() + "\"\n");
  EXPECT_NE(s.what.find("secret/secret.glsl"), std::string::npos) << s.what;
}

TEST_F(Confine, DotDotOutOfTheSceneIsRefused) {
  const ErrorInfo e = refused("\n\n#include \"../../secret/secret.glsl\"\n");
  EXPECT_EQ(e.line, 3);
  EXPECT_NE(e.what.find("secret/secret.glsl"), std::string::npos) << e.what;
  // Deep enough to reach /: still refused, also for a file that does not
  // exist (errors do not tell what exists out there).
  refused("#include \"../../../../../../../../../../etc/passwd\"\n");
  const ErrorInfo missing = refused("#include \"../../nope/none.glsl\"\n");
  EXPECT_NE(missing.what.find("outside"), std::string::npos) << missing.what;
}

TEST_F(Confine, DotDotThatStaysInsideIsFine) {
  put(scene() / "sub/a.glsl", "#include \"../b.glsl\"\nfloat a();\n");
  put(scene() / "b.glsl", "float b();\n");
  const ShaderSource s = preprocess("#include \"sub/a.glsl\"\n#include \"../lib/lib.glsl\"\n", "root.glsl", scene(),
                                    confined());
  EXPECT_NE(s.text.find("float b();"), std::string::npos);
  EXPECT_NE(s.text.find("float lib()"), std::string::npos);
}

TEST_F(Confine, SymlinkedFileLeadingOutIsRefused) {
  fs::create_symlink(secret(), scene() / "innocent.glsl");
  const ErrorInfo e = refused("#include \"innocent.glsl\"\n");
  // The canonical path is what is named: the user sees where it leads.
  EXPECT_NE(e.what.find("secret/secret.glsl"), std::string::npos) << e.what;
  // Also when the symlink is found through the library's include path.
  fs::create_symlink(secret(), lib() / "sneaky.glsl");
  refused("#include <sneaky.glsl>\n");
}

TEST_F(Confine, SymlinkedDirectoryLeadingOutIsRefused) {
  fs::create_directory_symlink(tmp, scene() / "up");
  refused("#include \"up/secret/secret.glsl\"\n");
}

TEST_F(Confine, SymlinkThatStaysInsideIsFine) {
  put(lib() / "real.glsl", "float real_one();\n");
  fs::create_symlink(lib() / "real.glsl", scene() / "alias.glsl");
  const ShaderSource s = preprocess("#include \"alias.glsl\"\n", "root.glsl", scene(), confined());
  EXPECT_NE(s.text.find("float real_one();"), std::string::npos);
  ASSERT_EQ(s.dependencies.size(), 1u);
  EXPECT_EQ(s.dependencies[0], fs::canonical(lib() / "real.glsl"));
}

TEST_F(Confine, NestedIncludeIsReportedAtItsOwnFileAndLine) {
  put(scene() / "a.glsl", "// a\n// a\n#include \"../../secret/secret.glsl\"\n");
  try {
    preprocess("#include \"a.glsl\"\n", "root.glsl", scene(), confined());
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().line, 3);
    EXPECT_NE(e.info().file.find("a.glsl"), std::string::npos) << e.what();
  }
}

TEST_F(Confine, NoRootsMeansUnconfined) {
  PreprocessOptions open;
  const ShaderSource s = preprocess("#include \"" + secret().string() + "\"\n", "root.glsl", scene(), open);
  EXPECT_NE(s.text.find(kSecret), std::string::npos);
}

TEST_F(Confine, WithinRootsComparesWholePathComponents) {
  EXPECT_TRUE(within_roots(scene() / "x.glsl", {scene()}));
  EXPECT_TRUE(within_roots(scene() / "a/../x.glsl", {scene()}));
  EXPECT_FALSE(within_roots(scene() / "../x.glsl", {scene()}));
  // "scene2" starts with "scene" but is not inside it.
  EXPECT_FALSE(within_roots(tmp / "project/scene2/x.glsl", {scene()}));
  EXPECT_FALSE(within_roots("/etc/passwd", {scene(), lib()}));
  EXPECT_FALSE(within_roots(scene() / "x.glsl", {}));
}

// Bounded work in the preprocessor: a chain of 10000 includes used to
// overflow the stack (one recursion per level); 200 levels is the limit.
TEST_F(Confine, IncludeDepthIsBounded) {
  constexpr int kChain = 250;
  for (int i = 0; i < kChain; ++i)
    put(scene() / ("d" + std::to_string(i) + ".glsl"),
        i + 1 < kChain ? "#include \"d" + std::to_string(i + 1) + ".glsl\"\n" : "float deepest();\n");
  try {
    preprocess("#include \"d0.glsl\"\n", "root.glsl", scene(), confined());
    FAIL() << "a 250-level chain was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nested more than 200 levels"), std::string::npos) << e.what();
    // d0 is level 1: d199 (level 200) may not include d200.
    EXPECT_NE(e.info().file.find("d199.glsl"), std::string::npos) << e.what();
  }
  // Exactly 200 levels are fine: d50 .. d249.
  EXPECT_NO_THROW(preprocess("#include \"d50.glsl\"\n", "root.glsl", scene(), confined()));
  EXPECT_THROW(preprocess("#include \"d49.glsl\"\n", "root.glsl", scene(), confined()), Error);
}

// The scene level: assemble_scene with a map file outside the scene's
// directory, then the same with --allow-include (AssembleOptions).
class ConfineScene : public Confine {
 protected:
  void SetUp() override {
    Confine::SetUp();
    put(lib() / "prelude.glsl", "// prelude\n");
    put(lib() / "primitives.glsl", "// primitives\n");
    put(lib() / "operators.glsl", "// operators\n");
    put(lib() / "noise.glsl", "// noise\n");
    put(lib() / "main.frag", "void main() {}\n");
    put(lib() / "post.frag", "void main() {}\n");
    s.file = scene() / "scene.toml";
    Material m;
    m.name = "floor";
    s.materials = {m};
    opts.shader_dir = lib();
  }
  Scene s;
  AssembleOptions opts;
};

TEST_F(ConfineScene, MapOutsideTheSceneIsRefusedAtScenemap) {
  s.map_file = secret();
  try {
    assemble_scene(s, opts);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().key, "scene.map");
    EXPECT_NE(e.info().file.find("scene.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("secret/secret.glsl"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(kSecret), std::string::npos) << e.what();
  }
  // Widened: the same scene assembles and reads the file (given a map()).
  put(secret(), std::string("// ") + kSecret + "\nvec2 map(vec3 p) { return vec2(1.0, 0.0); }\n");
  opts.allow_include = {secret().parent_path()};
  EXPECT_NE(assemble_scene(s, opts).text.find(kSecret), std::string::npos);
}

TEST_F(ConfineScene, MapIncludingOutsideIsRefusedUntilAllowed) {
  s.map_file = scene() / "map.glsl";
  put(s.map_file, "#include \"../../secret/secret.glsl\"\nvec2 map(vec3 p) { return vec2(secret(), 0.0); }\n");
  try {
    assemble_scene(s, opts);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().line, 1);
    EXPECT_NE(e.info().file.find("map.glsl"), std::string::npos) << e.what();
  }
  opts.allow_include = {tmp / "secret"};
  EXPECT_NO_THROW(assemble_scene(s, opts));
}

TEST_F(ConfineScene, WrappedShadertoyOutsideItsSceneIsRefused) {
  put(tmp / "elsewhere/st.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  EXPECT_THROW(assemble_shadertoy(tmp / "elsewhere/st.glsl", opts, scene() / "scene.toml"), Error);
  // Bare (named on the command line): its own directory is the root, even
  // when reached through a symlink.
  EXPECT_NO_THROW(assemble_shadertoy(tmp / "elsewhere/st.glsl", opts));
  fs::create_symlink(tmp / "elsewhere/st.glsl", scene() / "link.glsl");
  EXPECT_NO_THROW(assemble_shadertoy(scene() / "link.glsl", opts));
  // ...whose includes stay confined.
  put(tmp / "elsewhere/inc.glsl", "#include \"../secret/secret.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) {}\n");
  EXPECT_THROW(assemble_shadertoy(tmp / "elsewhere/inc.glsl", opts), Error);
}

}  // namespace
}  // namespace ms
