// marchstudio bench through the real binary: its counting pass against an
// independent CPU tracer, the JSON against the field list in docs/bench.md
// (both directions), sane timings, and bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <regex>
#include <set>

#include "cpu_tracer.h"
#include "run.h"
#include "scene/load.h"
#include "scene/quality.h"

namespace ms::test {
namespace {

using nlohmann::json;

std::string scene(const std::string& name) { return (source_dir() / "scenes" / (name + ".toml")).string(); }

json bench_json(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"bench"};
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back("--json");
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(r.out);  // throws (and fails the test) on anything but one JSON value
}

// Every JSON pointer listed in docs/bench.md's schema table.
std::set<std::string> documented_fields() {
  const std::string doc = read_file(source_dir() / "docs/bench.md");
  const size_t from = doc.find("## JSON schema");
  EXPECT_NE(from, std::string::npos);
  static const std::regex row(R"(\n\| `(/[a-z0-9_/]+)` \|)");
  std::set<std::string> out;
  for (std::sregex_iterator it(doc.begin() + from, doc.end(), row), end; it != end; ++it) out.insert((*it)[1]);
  return out;
}

// JSON pointers of every leaf (arrays count as leaves).
void leaves(const json& j, const std::string& at, std::set<std::string>& out) {
  if (!j.is_object()) {
    out.insert(at);
    return;
  }
  for (const auto& [k, v] : j.items()) leaves(v, at + "/" + k, out);
}

// The CPU tracer mirrors plain sphere tracing of the whole field, the
// textbook preset; the default tracer is checked in test_presets.cpp.
TEST(Bench, CountingPassAgreesWithTheCpuTracer) {
  constexpr int W = 24, H = 14;
  const json j =
      bench_json({scene("seed"), "--size", "24x14", "--frames", "1", "--warmup", "0", "--preset", "textbook"});
  Scene seed = load_scene(scene("seed"));
  seed.quality = with_preset(seed.quality, "textbook");
  double sum = 0;
  int capped = 0, hits = 0, max_steps = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const CpuTrace c = cpu_trace(cpu_camera_ray(seed.camera, W, H, x, y), seed.quality);
      sum += c.steps;
      capped += c.capped;
      hits += c.hit;
      max_steps = std::max(max_steps, c.steps);
    }
  const double cpu_mean = sum / (W * H);
  const json& cost = j.at("cost");
  EXPECT_EQ(cost.at("pixels").get<int>(), W * H);
  // Float differences between the CPU and llvmpipe may flip a step on a few
  // pixels (see test_aov.cpp): the mean must agree within 1%.
  EXPECT_NEAR(cost.at("primary_steps").at("mean").get<double>(), cpu_mean, 0.01 * cpu_mean);
  EXPECT_NEAR(cost.at("primary_steps").at("max").get<double>(), max_steps, 1.0);
  EXPECT_NEAR(cost.at("step_cap_fraction").get<double>(), static_cast<double>(capped) / (W * H), 1.5 / (W * H));
  EXPECT_NEAR(cost.at("hit_fraction").get<double>(), static_cast<double>(hits) / (W * H), 3.5 / (W * H));
}

TEST(Bench, JsonHasExactlyTheDocumentedFields) {
  const json j = bench_json({scene("seed"), "--size", "32x18", "--frames", "3", "--warmup", "1"});
  const std::set<std::string> doc = documented_fields();
  ASSERT_GT(doc.size(), 30u) << "could not read the schema table in docs/bench.md";
  std::set<std::string> got;
  leaves(j, "", got);
  for (const std::string& f : doc) EXPECT_TRUE(got.count(f)) << "documented but missing: " << f;
  for (const std::string& f : got) EXPECT_TRUE(doc.count(f)) << "present but undocumented: " << f;

  EXPECT_EQ(j.at("schema"), "marchstudio.bench/1");
  EXPECT_EQ(j.at("settings").at("width"), 32);
  EXPECT_EQ(j.at("settings").at("frames"), 3);
  EXPECT_FALSE(j.at("machine").at("gl_renderer").get<std::string>().empty());
  EXPECT_EQ(j.at("scene").at("name"), "seed");
}

TEST(Bench, TimingsAreOrderedAndPositive) {
  const json j = bench_json({scene("seed"), "--size", "32x18", "--frames", "5", "--warmup", "1"});
  const json& st = j.at("startup_ms");
  EXPECT_GT(st.at("link").get<double>(), 0.0);
  EXPECT_GE(st.at("compile_link").get<double>(), st.at("link").get<double>());
  EXPECT_GE(st.at("first_frame").get<double>(), st.at("compile_link").get<double>());
  EXPECT_TRUE(j.at("frame_ms").at("gpu_timer").get<bool>()) << "llvmpipe supports GL_TIME_ELAPSED";
  for (const char* clock : {"gpu", "wall"}) {
    const json& f = j.at("frame_ms").at(clock);
    EXPECT_GT(f.at("min").get<double>(), 0.0) << clock;
    EXPECT_LE(f.at("min").get<double>(), f.at("median").get<double>()) << clock;
    EXPECT_LE(f.at("median").get<double>(), f.at("p95").get<double>()) << clock;
    EXPECT_LE(f.at("p95").get<double>(), f.at("max").get<double>()) << clock;
  }
  // A shaded pixel costs more map() calls than its primary steps alone.
  const json& c = j.at("cost");
  EXPECT_GT(c.at("sdf_evals").at("mean").get<double>(), c.at("primary_steps").at("mean").get<double>());
  EXPECT_GT(c.at("shadow_steps").at("max").get<double>(), 0.0);
  EXPECT_GT(c.at("reflection_steps").at("max").get<double>(), 0.0);
}

TEST(Bench, TableForPeople) {
  const RunResult r = run_marchstudio({"bench", scene("seed"), "--size", "16x9", "--frames", "1", "--warmup", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* s : {"primary steps", "shadow steps", "reflection steps", "sdf evaluations", "step-cap",
                        "compile+link", "median", "p95", "llvmpipe"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << " not in:\n" << r.out;
}

// A per-frame host cost: every frame sets the same
// uniforms, so their locations are asked of the GL in the first frames and
// kept (render/program.h). Counted, not timed: scene and Shadertoy uniforms,
// fused and post-pass frames, bloom, both dispatches.
TEST(Bench, NoUniformLookupsAfterTheFirstFrame) {
  const std::string bloom = (source_dir() / "tests/data/bloom/orbs.toml").string();
  const std::string toy = (source_dir() / "tests/data/shader/shadertoy/ok.glsl").string();
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {scene("seed"), "--dispatch", "fragment"},
           {scene("seed"), "--dispatch", "compute", "--spp", "2"},
           {scene("stilllife"), "--dispatch", "fragment", "--spp", "2"},
           {bloom, "--spp", "2"},
           {toy, "--dispatch", "compute"},
       }) {
    std::vector<std::string> a = args;
    a.insert(a.end(), {"--size", "32x18", "--frames", "4", "--warmup", "2"});
    const json j = bench_json(a);
    const json& n = j.at("uniform_lookups");
    EXPECT_GT(n.at("first_frames").get<long long>(), 10) << args[0];  // uResolution, the camera, ...
    EXPECT_EQ(n.at("later_frames").get<long long>(), 0) << args[0] << " " << args[2];
  }
}

// A per-frame host cost: a program keeps its uniforms,
// so a frame sends only the values that differ from the last one
// (render/program.h). A still scene at spp 1 changes nothing; at spp 4 the
// jitter changes four times a frame (one tile: uMsRect stays).
TEST(Bench, OnlyChangedUniformsAreSentAgain) {
  const std::string toy = (source_dir() / "tests/data/shader/shadertoy/ok.glsl").string();
  struct Case {
    std::vector<std::string> args;
    double per_frame;
  };
  for (const Case& c : std::vector<Case>{
           {{scene("seed"), "--dispatch", "fragment"}, 0},
           {{scene("stilllife"), "--dispatch", "compute"}, 0},
           {{scene("seed"), "--dispatch", "fragment", "--spp", "4"}, 4},
           {{scene("seed"), "--dispatch", "compute", "--spp", "4"}, 4},
           {{toy, "--dispatch", "fragment"}, 0},
       }) {
    std::vector<std::string> a = c.args;
    a.insert(a.end(), {"--size", "32x18", "--frames", "4", "--warmup", "2"});
    const json j = bench_json(a);
    const json& n = j.at("uniform_sets");
    EXPECT_GT(n.at("first_frames").get<long long>(), 4) << c.args[0];  // uResolution, the camera, ...
    EXPECT_EQ(n.at("per_timed_frame").get<double>(), c.per_frame) << c.args[0] << " " << c.args[2];
  }
}

TEST(Bench, BadInputExitsTwo) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"bench", scene("seed"), "--frames", "0"},
           {"bench", scene("seed"), "--warmup", "-1"},
           {"bench", scene("seed"), "--spp", "5000"},
           {"bench", scene("seed"), "--size", "12by4"},
           {"bench", (source_dir() / "scenes/missing.toml").string()},
       }) {
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 2) << args.back() << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace ms::test
