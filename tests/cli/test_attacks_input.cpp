// Attacks on the input side, through the real binary: shaders that took the
// process down (a deep expression, a macro bomb, an include diamond),
// `#error` under a warm shader cache, non-regular input files, and flags
// or scene keys accepted without a word. Each case failed before the fix
// (crash, hang, 24 GB, exit 0); docs/reliability.md lists them.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <string>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A Shadertoy shader whose one statement sums `terms` terms.
std::string sum_shader(int terms) {
  std::string e = "f.x";
  e.reserve(static_cast<size_t>(terms) * 6);
  for (int i = 1; i < terms; ++i) e += " + f.x";
  return "void mainImage(out vec4 c, in vec2 f) {\n  float k = " + e + ";\n  c = vec4(k * 0.0);\n}\n";
}

const char* kMain = "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }\n";

// Compile outcomes must not come from an earlier run's disk cache.
std::string fresh_cache(const TempDir& dir) { return "MESA_SHADER_CACHE_DIR='" + (dir / "cache").string() + "' "; }

TEST(DeepExpression, CompilesWhereTheMainStackWouldOverflow) {
  TempDir dir;
  // 4000 levels need about 2.7 MiB of Mesa's stack: with a 1 MiB main
  // thread this died with SIGSEGV; the compile now runs on its own stack.
  write_file(dir / "sum.glsl", sum_shader(4000));
  const RunResult r = run_marchstudio({"render", "sum.glsl", "--size", "8x8", "-o", "sum.png"}, dir.path(),
                                      "ulimit -s 1024; export " + fresh_cache(dir) + "; ");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "sum.png"));
}

TEST(DeepExpression, ADeeperOneIsRefusedAtItsLineBeforeTheDriver) {
  TempDir dir;
  write_file(dir / "sum.glsl", sum_shader(60000));
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_marchstudio({"render", "sum.glsl", "-o", "sum.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("sum.glsl:2: expression nested more than 50000 levels deep"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 20.0);
  EXPECT_FALSE(fs::exists(dir / "sum.png"));
}

TEST(MacroBomb, StopsAtTheExpansionBudgetInSeconds) {
  TempDir dir;
  std::string bomb = "#define A0 f.x\n";
  for (int i = 1; i <= 29; ++i)
    bomb += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + ", A" + std::to_string(i - 1) + "\n";
  write_file(dir / "bomb.glsl", bomb + "void mainImage(out vec4 c, in vec2 f) { c = vec4(A29); }\n");
  const auto t0 = std::chrono::steady_clock::now();
  // Mesa's own expansion reached 7 GB here; a 2 GB address-space limit
  // would kill the process if anything still expanded it. ASan reserves
  // terabytes of shadow memory, so there the limit cannot be set.
#if defined(__SANITIZE_ADDRESS__)
  const std::string limit;
#else
  const std::string limit = "ulimit -v 2000000; ";
#endif
  const RunResult r = run_marchstudio({"render", "bomb.glsl", "-o", "bomb.png"}, dir.path(), limit);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bomb.glsl:31: macro expansion makes more than 1048576 tokens"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 20.0);
  EXPECT_TRUE(dir.entries() == std::vector<std::string>{"bomb.glsl"});
}

TEST(IncludeDiamond, StopsAtTheSizeBudgetInSeconds) {
  TempDir dir;
  for (int i = 0; i <= 40; ++i)
    write_file(dir / ("f" + std::to_string(i) + ".glsl"),
               i < 40 ? "#include \"f" + std::to_string(i + 1) + ".glsl\"\n#include \"f" + std::to_string(i + 1) +
                            ".glsl\"\n"
                      : "float leaf() { return 1.0; }\n");
  write_file(dir / "main.glsl", std::string("#include \"f0.glsl\"\n") + kMain);
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_marchstudio({"render", "main.glsl", "-o", "out.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the shader is larger than 8 MiB with its includes expanded"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'f40.glsl' is included"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 20.0);
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(HashError, FailsEveryTimeWhateverTheShaderCacheHolds) {
  TempDir dir;
  const std::string cache = fresh_cache(dir);
  write_file(dir / "m.glsl", kMain);
  ASSERT_EQ(run_marchstudio({"render", "m.glsl", "--size", "8x8", "-o", "a.png"}, dir.path(), cache).exit_code, 0);
  // Now the cache is warm; the same code behind an #error must still fail.
  write_file(dir / "m.glsl", std::string("#error this shader needs a newer marchstudio\n") + kMain);
  for (int run = 0; run < 2; ++run) {
    const RunResult r = run_marchstudio({"render", "m.glsl", "--size", "8x8", "-o", "b.png"}, dir.path(), cache);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("m.glsl:1: #error this shader needs a newer marchstudio"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "b.png"));
}

TEST(NonRegularInputs, AreRefusedAtOnceAndNamedForWhatTheyAre) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo.png").c_str(), 0600), 0);
  fs::create_directory(dir / "adir.png");
  write_file(dir / "m.glsl", kMain);
  ASSERT_EQ(run_marchstudio({"render", "m.glsl", "--size", "8x8", "-o", "ok.png"}, dir.path()).exit_code, 0);
  const struct {
    std::string a, what;
  } cases[] = {{"fifo.png", "is a FIFO (named pipe), not a regular file"},
               {"/dev/zero", "is a device, not a regular file"},
               {"adir.png", "is a directory, not a regular file"},
               {"missing.png", "not found"}};
  for (const auto& c : cases) {
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult r = run_marchstudio({"compare", c.a, "ok.png"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << c.a << ": " << r.err;
    EXPECT_NE(r.err.find(c.what), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_LT(seconds_since(t0), 10.0) << c.a;
  }
  // The same reader for scenes and shaders (a .png input is refused as an
  // image by its name alone, so the shader FIFO has a shader's name).
  ASSERT_EQ(::mkfifo((dir / "fifo.glsl").c_str(), 0600), 0);
  const RunResult s = run_marchstudio({"render", "fifo.glsl"}, dir.path());
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("is a FIFO"), std::string::npos) << s.err;
}

TEST(SilentlyAccepted, BadFlagValuesAreRefused) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const struct {
    std::vector<std::string> args;
    std::string says;
  } cases[] = {
      {{"--frames", "", "-o", "f_%04d.png"}, "--frames: must not be empty"},
      {{"--spp", "0"}, "--spp"},
      {{"--time", "1e300"}, "--time: 1e300 is too large for a 32-bit float"},
      {{"--disable", "shadow"}, "'shadow' is not one of shadows, reflections, ao, checker-filter, bloom (did you mean "
                                "'shadows'?)"},
      {{"--aov", "dpeth", "-o", "x.exr"}, "(did you mean 'depth'?)"},
      {{"--sppp", "3"}, "unknown flag '--sppp' for 'render' (did you mean '--spp'?)"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"render", "m.glsl", "--size", "8x8"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << c.says << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"m.glsl"}) << c.says;
  }
  const RunResult sub = run_marchstudio({"rendr", "m.glsl"}, dir.path());
  EXPECT_EQ(sub.exit_code, 2);
  EXPECT_NE(sub.err.find("unknown subcommand 'rendr' (did you mean 'render'?)"), std::string::npos) << sub.err;
}

TEST(SilentlyAccepted, ShadertoyWrappersAndAnimationTimesAreChecked) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  write_file(dir / "w.toml", "[scene]\nshadertoy = \"m.glsl\"\n[render]\nwidth = 8\n[camera]\nfov = 30.0\n");
  RunResult r = run_marchstudio({"render", "w.toml"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("w.toml:5: 'camera' has no effect on a Shadertoy shader"), std::string::npos) << r.err;
  write_file(dir / "w.toml", "[scene]\nshadertoy = \"m.glsl\"\n[render]\nwidth = 8\ntonemap = \"aces\"\n");
  r = run_marchstudio({"render", "w.toml"}, dir.path());
  EXPECT_NE(r.err.find("w.toml:5: 'render.tonemap' has no effect"), std::string::npos) << r.err;
  const std::string scene = read_file(source_dir() / "scenes/seed.toml");
  write_file(dir / "seed.glsl", read_file(source_dir() / "scenes/seed.glsl"));
  write_file(dir / "a.toml", scene + "\n[[animation]]\ntarget = \"camera.fov\"\nkeys = [[0.0, 40.0], [1e308, 50.0]]\n");
  r = run_marchstudio({"render", "a.toml", "-o", "a.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is too large for a 32-bit float"), std::string::npos) << r.err;
}

TEST(ErrorText, SaysWhatIsWrongWhereItIs) {
  TempDir dir;
  // A path with a newline stays one line.
  fs::create_directory(dir / "two\nlines");
  const RunResult nl = run_marchstudio({"render", "two\nlines/none.toml"}, dir.path());
  EXPECT_EQ(nl.exit_code, 2);
  EXPECT_NE(nl.err.find("two\\nlines/none.toml: scene file not found"), std::string::npos) << nl.err;
  EXPECT_EQ(std::count(nl.err.begin(), nl.err.end(), '\n'), 1) << nl.err;
  // A map file without map() is blamed on the scene, not the library.
  const std::string scene = read_file(source_dir() / "scenes/seed.toml");
  write_file(dir / "seed.toml", scene);
  write_file(dir / "seed.glsl", "float notmap(vec3 p) { return length(p) - 1.0; }\n");
  const RunResult nomap = run_marchstudio({"render", "seed.toml", "-o", "x.png"}, dir.path());
  EXPECT_EQ(nomap.exit_code, 2);
  EXPECT_NE(nomap.err.find("seed.toml: scene.map: the map file defines no map() function"), std::string::npos)
      << nomap.err;
  // A map file rendered as if it were a shader points at its scene.
  write_file(dir / "seed.glsl", read_file(source_dir() / "scenes/seed.glsl"));
  const RunResult bare = run_marchstudio({"render", "seed.glsl", "-o", "x.png"}, dir.path());
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("it defines map(): render its scene, seed.toml"), std::string::npos) << bare.err;
  // -v shows every diagnostic behind "+N more".
  write_file(dir / "bad.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(nope_a) + nope_b; }\n");
  const RunResult quiet = run_marchstudio({"render", "bad.glsl", "-o", "x.png"}, dir.path(), fresh_cache(dir));
  EXPECT_NE(quiet.err.find("more; -v prints them all"), std::string::npos) << quiet.err;
  EXPECT_EQ(quiet.err.find("nope_b"), std::string::npos) << quiet.err;
  const RunResult loud = run_marchstudio({"render", "bad.glsl", "-o", "x.png", "-v"}, dir.path(), fresh_cache(dir));
  EXPECT_NE(loud.err.find("bad.glsl:1: error: `nope_b' undeclared"), std::string::npos) << loud.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace ms::test
