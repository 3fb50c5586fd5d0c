// Specialized against generic shaders through the real binary
// (docs/specialization.md): the same image and the same steps per pixel for
// every scene, --no-specialize on render, bench and view; and the program
// cache in a real GL context.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "gl/context.h"
#include "io/image_io.h"
#include "render/program_cache.h"
#include "run.h"
#include "shader/assemble.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// The shipped scenes and the specialization test scenes (no mirror; two
// directional lights and no checker; animated values).
std::vector<fs::path> scenes() {
  std::vector<fs::path> out;
  for (const fs::path& dir : {source_dir() / "scenes", fs::path(MARCH_TEST_DATA) / "specialize"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".toml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

Image render(TempDir& dir, const fs::path& scene, const std::string& name, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render", scene.string(), "-o", (dir / name).string(), "--size", "96x54"};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(dir / name);
}

// Largest difference of one channel over all pixels.
float max_diff(const Image& a, const Image& b, int channel) {
  float m = 0.0f;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) m = std::max(m, std::abs(a.at(x, y, channel) - b.at(x, y, channel)));
  return m;
}

// Linear radiance (EXR, no tone map). Measured: at most 3.6e-7, that is
// float rounding where the compiler folds a constant differently from a
// uniform; most scenes are bit-identical. The tolerance is 1e-5 per channel,
// 27x that and still 400x under one 8-bit level.
constexpr float kTolerance = 1e-5f;

TEST(Specialize, ImagesMatchTheGenericShaderForEveryScene) {
  TempDir dir;
  const std::vector<fs::path> all = scenes();
  ASSERT_GE(all.size(), 6u);
  for (const fs::path& scene : all) {
    const Image spec = render(dir, scene, "spec.exr", {});
    const Image gen = render(dir, scene, "gen.exr", {"--no-specialize"});
    ASSERT_EQ(spec.width, gen.width);
    ASSERT_EQ(spec.channels, gen.channels);
    for (int c = 0; c < 3; ++c) EXPECT_LE(max_diff(spec, gen, c), kTolerance) << scene << " channel " << c;
  }
}

TEST(Specialize, StepsPerPixelAreIdentical) {
  TempDir dir;
  for (const fs::path& scene : scenes()) {
    const Image spec = render(dir, scene, "spec.exr", {"--aov", "steps,cost,hit"});
    const Image gen = render(dir, scene, "gen.exr", {"--aov", "steps,cost,hit", "--no-specialize"});
    ASSERT_EQ(spec.channels, gen.channels);
    for (const char* name : {"steps", "shadow_steps", "reflection_steps", "sdf_evals", "step_cap", "hit"}) {
      const auto it = std::find(spec.channels.begin(), spec.channels.end(), name);
      ASSERT_NE(it, spec.channels.end()) << name;
      EXPECT_EQ(max_diff(spec, gen, static_cast<int>(it - spec.channels.begin())), 0.0f) << scene << " " << name;
    }
  }
}

TEST(Specialize, EveryCommandHasNoSpecialize) {
  const std::string matte = (fs::path(MARCH_TEST_DATA) / "specialize/matte.toml").string();
  RunResult r = run_marchstudio({"render", matte, "--print-shader"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\n#define SPECIALIZED 1\n"), std::string::npos);
  EXPECT_NE(r.out.find("\n#define MAX_BOUNCES 0\n"), std::string::npos);
  r = run_marchstudio({"render", matte, "--print-shader", "--no-specialize"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("#define SPECIALIZED 1"), std::string::npos);
  EXPECT_NE(r.out.find("\n#define MAX_BOUNCES 2\n"), std::string::npos);

  for (const char* flag : {"", "--no-specialize"}) {
    std::vector<std::string> args = {"bench", matte, "--size", "16x9", "--frames", "1", "--warmup", "0", "--json"};
    if (*flag) args.push_back(flag);
    r = run_marchstudio(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("settings").at("specialize"), *flag ? "generic" : "folded");
  }
  r = run_marchstudio({"view", "--help"});
  EXPECT_NE(r.out.find("--no-specialize"), std::string::npos) << r.out;
}

TEST(ProgramCache, ASeenShaderIsNotCompiledAgain) {
  std::unique_ptr<Context> ctx;
  try {
    ctx = create_headless_context(Backend::automatic);
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no GL context: " << e.what();
  }
  auto frag = [](const std::string& colour) {
    ShaderSource s;
    s.text = "#version 450 core\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(" + colour + "); }\n";
    s.files = {"test.frag"};
    return s;
  };
  const std::string vs = fullscreen_vertex_source();
  ProgramCache cache(2);
  bool hit = true;
  const auto a = cache.get(vs, frag("1.0"), &hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(cache.get(vs, frag("1.0"), &hit), a);
  EXPECT_TRUE(hit) << "the same source is a cache hit";
  const auto b = cache.get(vs, frag("0.5"), &hit);
  EXPECT_FALSE(hit);
  EXPECT_NE(a->id(), b->id());
  EXPECT_THROW(cache.get(vs, frag("nope"), &hit), Error);
  EXPECT_EQ(cache.size(), 2u) << "a failed compile adds nothing";
  cache.get(vs, frag("0.25"));  // capacity 2: the least recently used (a) goes
  EXPECT_EQ(cache.size(), 2u);
  cache.get(vs, frag("0.5"), &hit);
  EXPECT_TRUE(hit);
  cache.get(vs, frag("1.0"), &hit);
  EXPECT_FALSE(hit) << "evicted";
  EXPECT_EQ(cache.hits(), 2);
  EXPECT_EQ(cache.misses(), 4);
  cache.clear();
}

// The viewer's compile worker links on another context and the UI thread
// put()s the program (live/compile_worker.h): the next get() is a hit.
TEST(ProgramCache, APutProgramIsAHit) {
  std::unique_ptr<Context> ctx;
  try {
    ctx = create_headless_context(Backend::automatic);
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no GL context: " << e.what();
  }
  ShaderSource s;
  s.text = "#version 450 core\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(0.5); }\n";
  s.files = {"test.frag"};
  const std::string vs = fullscreen_vertex_source();
  ProgramCache cache(2);
  auto linked = std::make_shared<const Program>(vs, s);
  EXPECT_FALSE(cache.contains(vs, s));
  cache.put(vs, s, linked);
  EXPECT_TRUE(cache.contains(vs, s));
  bool hit = false;
  EXPECT_EQ(cache.get(vs, s, &hit), linked);
  EXPECT_TRUE(hit);
  cache.put(vs, s, std::make_shared<const Program>(vs, s));  // already there: the first one stays
  EXPECT_EQ(cache.get(vs, s), linked);
  EXPECT_EQ(cache.size(), 1u);
  cache.clear();
}

}  // namespace
}  // namespace ms::test
