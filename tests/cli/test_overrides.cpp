// --set key=value and --uniform NAME=VALUE through the real binary: a render
// with an override equals, pixel for pixel, one of a copy of the scene (or
// map) edited to say the same; bad overrides are one-line errors naming the
// flag, exit 2, and write nothing. The TOML path logic itself:
// tests/unit/test_scene_overrides.cpp.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "io/image_io.h"
#include "run.h"

using namespace ms::test;
namespace fs = std::filesystem;

namespace {

const fs::path kSeed = source_dir() / "scenes/seed.toml";
const fs::path kBall = source_dir() / "tests/data/bounds/ball.toml";

// `text` with `from` replaced (exactly once) by `to`.
std::string edited(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = read_file(file);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << file;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from << " twice in " << file;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// A copy of a scene and its map in `dir`, each edited (or not).
fs::path copy_scene(const fs::path& scene, const fs::path& dir, const std::string& toml, const std::string& glsl = {}) {
  const fs::path map = scene.parent_path() / (scene.stem().string() + ".glsl");
  write_file(dir / scene.filename(), toml.empty() ? read_file(scene) : toml);
  write_file(dir / map.filename(), glsl.empty() ? read_file(map) : glsl);
  return dir / scene.filename();
}

ms::Image render(const fs::path& scene, const fs::path& out, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"render", scene.string(), "--size", "64x36", "-o", out.string()};
  args.insert(args.end(), more.begin(), more.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return ms::read_image(out);
}

// Exact equality: both renders run the same program on the same values.
void expect_same_pixels(const ms::Image& a, const ms::Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differ, 0u) << "values that differ";
}

bool any_pixel_differs(const ms::Image& a, const ms::Image& b) { return a.pixels != b.pixels; }

}  // namespace

TEST(SetOverride, EqualsAnEditedSceneFile) {
  TempDir dir;
  const fs::path copy = copy_scene(kSeed, dir.path(), edited(kSeed, "fov      = 45.0", "fov      = 30.0"));
  const ms::Image from_flag = render(kSeed, dir / "flag.png", {"--set", "camera.fov=30"});
  expect_same_pixels(from_flag, render(copy, dir / "file.png"));
  EXPECT_TRUE(any_pixel_differs(from_flag, render(kSeed, dir / "plain.png")));  // it did something
}

TEST(SetOverride, AMaterialByNameEqualsAnEditedSceneFile) {
  TempDir dir;
  const fs::path copy =
      copy_scene(kSeed, dir.path(), edited(kSeed, "color        = [0.85, 0.10, 0.06]", "color        = [0.1, 0.7, 0.2]"));
  const ms::Image from_flag = render(kSeed, dir / "flag.png", {"--set", "materials.ball.color=[0.1,0.7,0.2]"});
  expect_same_pixels(from_flag, render(copy, dir / "file.png"));
  EXPECT_TRUE(any_pixel_differs(from_flag, render(kSeed, dir / "plain.png")));
}

TEST(SetOverride, RepeatedIndexedAndCreatedKeysEqualAnEditedFile) {
  TempDir dir;
  // seed.toml has no [quality]: the override creates it, as a file that adds one.
  std::string toml = edited(kSeed, "intensity   = 2.0", "intensity   = 3.5");
  toml += "\n[quality]\nmax_steps = 24\npreset = \"fast\"\n";
  const fs::path copy = copy_scene(kSeed, dir.path(), toml);
  const ms::Image from_flag = render(kSeed, dir / "flag.png",
                                     {"--set", "lights[0].intensity=1", "--set", "lights.0.intensity=3.5", "--set",
                                      "quality.max_steps=24", "--set", "quality.preset=fast"});
  expect_same_pixels(from_flag, render(copy, dir / "file.png"));
}

std::string fingerprint(const fs::path& image) {
  const RunResult r = run_marchstudio({"info", "--fingerprint", image.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

TEST(Overrides, ChangeTheFingerprint) {
  // camera.fov is a uniform, not shader text: the override itself is hashed.
  TempDir dir;
  render(kSeed, dir / "a.png");
  render(kSeed, dir / "b.png", {"--set", "camera.fov=30"});
  render(kSeed, dir / "c.png", {"--set", "camera.fov=30"});
  EXPECT_NE(fingerprint(dir / "a.png"), fingerprint(dir / "b.png"));
  EXPECT_EQ(fingerprint(dir / "b.png"), fingerprint(dir / "c.png"));  // and is the same for the same override
  render(kBall, dir / "d.png");
  render(kBall, dir / "e.png", {"--uniform", "uRadius=1.3"});
  EXPECT_NE(fingerprint(dir / "d.png"), fingerprint(dir / "e.png"));
}

struct BadFlag {
  const char* name;
  std::vector<std::string> args;
  std::string err;  // the whole stderr line, after "marchstudio: "
};

void PrintTo(const BadFlag& c, std::ostream* os) { *os << c.name; }

class BadOverride : public ::testing::TestWithParam<BadFlag> {};

TEST_P(BadOverride, IsOneLineNamingTheFlagAndWritesNothing) {
  const BadFlag& c = GetParam();
  TempDir dir;
  std::vector<std::string> args = {"render", c.args[0], "--size", "16x9", "-o", (dir / "out.png").string()};
  args.insert(args.end(), c.args.begin() + 1, c.args.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "marchstudio: " + c.err + "\n");
  EXPECT_TRUE(dir.entries().empty());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadOverride,
    ::testing::Values(
        BadFlag{"UnknownKey", {kSeed.string(), "--set", "camera.fvo=30"},
                "--set camera.fvo: unknown key 'camera.fvo' (did you mean 'fov'?)"},
        BadFlag{"WrongType", {kSeed.string(), "--set", "camera.fov=[1,2]"},
                "--set camera.fov: 'camera.fov' must be a number, not an array"},
        BadFlag{"NaN", {kSeed.string(), "--set", "camera.fov=nan"},
                "--set camera.fov: 'camera.fov' must be a finite number, got nan"},
        BadFlag{"OutOfRange", {kSeed.string(), "--set", "render.width=0"},
                "--set render.width: 'render.width' must be in [1, 16384], got 0"},
        BadFlag{"UnknownPreset", {kSeed.string(), "--set", "quality.preset=fsat"},
                "--set quality.preset: unknown value 'fsat' for 'quality.preset' (did you mean 'fast'?)"},
        BadFlag{"MissingMaterial", {kSeed.string(), "--set", "materials.bal.color=[1,0,0]"},
                "--set materials.bal.color: no entry of 'materials' is named 'bal' (did you mean 'ball'? names: "
                "floor, ball)"},
        BadFlag{"NoEquals", {kSeed.string(), "--set", "camera.fov"},
                "--set: expected KEY=VALUE, got 'camera.fov' (e.g. --set camera.fov=30)"},
        BadFlag{"NoKey", {kSeed.string(), "--set", "=30"}, "--set: expected KEY=VALUE, got '=30' (e.g. --set camera.fov=30)"},
        BadFlag{"NoValue", {kSeed.string(), "--set", "camera.fov="},
                "--set camera.fov: no value after '=' (e.g. --set camera.fov=30)"},
        BadFlag{"MalformedValue", {kSeed.string(), "--set", "camera.position=[1,2"},
                "--set camera.position: invalid value '[1,2' (a TOML value: 30, true, \"text\", [1, 0, 0]; a bare "
                "word is a string)"},
        BadFlag{"SmuggledSecondKey", {kSeed.string(), "--set", "camera.fov=30 x = 1"},
                "--set camera.fov: invalid value '30 x = 1' (a TOML value: 30, true, \"text\", [1, 0, 0]; a bare "
                "word is a string)"},
        BadFlag{"UniformOutOfRange", {kBall.string(), "--uniform", "uRadius=2.5"},
                "--uniform uRadius: 2.5 is outside the range [0.5, 2] of float 'uRadius' (its declaration says "
                "range(0.5, 2))"},
        BadFlag{"UniformUnknown", {kBall.string(), "--uniform", "uRadus=1"},
                "--uniform uRadus: no ranged uniform 'uRadus' in the scene (did you mean 'uRadius'? declared: uRadius)"},
        BadFlag{"UniformCount", {kBall.string(), "--uniform", "uRadius=[1,1]"},
                "--uniform uRadius: float 'uRadius' takes 1 number, got 2 (e.g. --uniform uRadius=0.5)"},
        BadFlag{"UniformNotANumber", {kBall.string(), "--uniform", "uRadius=big"},
                "--uniform uRadius: invalid value 'big' (a number, or [x, y, z] for a vector)"},
        BadFlag{"UniformNoneDeclared", {kSeed.string(), "--uniform", "uRadius=1"},
                "--uniform uRadius: the scene declares no ranged uniforms (--uniform sets a uniform declared with a "
                "// range(lo, hi) or // color comment (docs/scene-format.md))"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(UniformOverride, EqualsAnEditedMapFile) {
  TempDir dir;
  const fs::path map = kBall.parent_path() / "ball.glsl";
  const fs::path copy = copy_scene(kBall, dir.path(), {}, edited(map, "uRadius = 1.0;", "uRadius = 1.3;"));
  const ms::Image from_flag = render(kBall, dir / "flag.png", {"--uniform", "uRadius=1.3"});
  expect_same_pixels(from_flag, render(copy, dir / "file.png"));
  EXPECT_TRUE(any_pixel_differs(from_flag, render(kBall, dir / "plain.png")));
  // --print-shader shows the program rendered: the value as the initializer.
  const RunResult shader = run_marchstudio({"render", kBall.string(), "--uniform", "uRadius=1.3", "--print-shader"});
  EXPECT_EQ(shader.exit_code, 0) << shader.err;
  EXPECT_NE(shader.out.find("uniform float uRadius = 1.3;"), std::string::npos);
}

TEST(UniformOverride, AShadertoyShadersUniformEqualsAnEditedShader) {
  TempDir dir;
  const std::string shader =
      "uniform vec3 uTint = vec3(0.2, 0.4, 0.6); // color\n"
      "void mainImage(out vec4 c, in vec2 f) { c = vec4(uTint * (f.x / iResolution.x), 1.0); }\n";
  const std::string from = "vec3(0.2, 0.4, 0.6)";
  write_file(dir / "tint.glsl", shader);
  write_file(dir / "edited.glsl", std::string(shader).replace(shader.find(from), from.size(), "vec3(0.9, 0.5, 0.1)"));
  const ms::Image from_flag = render(dir / "tint.glsl", dir / "flag.png", {"--uniform", "uTint=0.9,0.5,0.1"});
  expect_same_pixels(from_flag, render(dir / "edited.glsl", dir / "file.png"));
  EXPECT_TRUE(any_pixel_differs(from_flag, render(dir / "tint.glsl", dir / "plain.png")));
}

TEST(Overrides, EverySubcommandThatLoadsASceneTakesThem) {
  // A bad override fails each before any GL work: the flag exists and is applied.
  for (const char* cmd : {"bench", "sweep", "view"}) {
    RunResult r = run_marchstudio({cmd, kSeed.string(), "--set", "camera.fvo=30"});
    EXPECT_EQ(r.exit_code, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("--set camera.fvo: unknown key"), std::string::npos) << cmd << ": " << r.err;
    r = run_marchstudio({cmd, kBall.string(), "--uniform", "uRadius=9"});
    EXPECT_EQ(r.exit_code, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("--uniform uRadius: 9 is outside"), std::string::npos) << cmd << ": " << r.err;
  }
  // A sequence too: its frames are the edited scene's.
  TempDir dir;
  const RunResult r = run_marchstudio({"render", kSeed.string(), "--frames", "0..0", "--size", "64x36", "-o",
                                       (dir / "f_%d.png").string(), "--set", "camera.fov=30"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path copy = copy_scene(kSeed, dir.path(), edited(kSeed, "fov      = 45.0", "fov      = 30.0"));
  expect_same_pixels(ms::read_image(dir / "f_0.png"), render(copy, dir / "file.png"));
}

TEST(Overrides, BenchRecordsThemAndCountsTheVariant) {
  auto bench = [](const fs::path& scene, std::vector<std::string> more) {
    std::vector<std::string> args = {"bench", scene.string(), "--json", "--frames", "1", "--warmup", "0",
                                     "--size", "32x18"};
    args.insert(args.end(), more.begin(), more.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const nlohmann::json plain = bench(kSeed, {});
  const nlohmann::json narrow = bench(kSeed, {"--set", "camera.fov=20", "--set", "camera.fov=30"});
  EXPECT_EQ(plain["settings"]["overrides"], nlohmann::json::array());
  EXPECT_EQ(narrow["settings"]["overrides"], (nlohmann::json{"--set camera.fov=20", "--set camera.fov=30"}));
  // A narrower view fills more of the frame with the ball: more pixels hit.
  EXPECT_GT(narrow["cost"]["hit_fraction"].get<double>(), plain["cost"]["hit_fraction"].get<double>());
  const nlohmann::json big = bench(kBall, {"--uniform", "uRadius=1.5"});
  EXPECT_EQ(big["settings"]["overrides"], (nlohmann::json{"--uniform uRadius=1.5"}));
  EXPECT_GT(big["cost"]["hit_fraction"].get<double>(), bench(kBall, {})["cost"]["hit_fraction"].get<double>());
}

TEST(Overrides, SetNeedsASceneFile) {
  TempDir dir;
  write_file(dir / "s.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  const RunResult r = run_marchstudio({"render", (dir / "s.glsl").string(), "--set", "camera.fov=30", "-o",
                                       (dir / "out.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--set camera.fov: --set needs a scene .toml"), std::string::npos) << r.err;
}
