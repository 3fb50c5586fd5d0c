// marchstudio sweep through the real binary (its CSV, JSON and plot are well
// formed and agree; the reference row has zero error against itself; bad
// flags), plus its pure parts: the grid, the Pareto front, and the exact
// reference (sphere recogniser, camera) against the tests' own CPU tracer.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "sweep/sweep.h"
#include "sweep/sweep_exact.h"
#include "sweep/sweep_grid.h"
#include "core/error.h"
#include "cpu_tracer.h"
#include "io/image_io.h"
#include "run.h"
#include "scene/load.h"

namespace ms::test {
namespace {

using nlohmann::json;

std::string scene(const std::string& name) { return (source_dir() / "scenes" / (name + ".toml")).string(); }

std::vector<std::vector<std::string>> read_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream ls(line);
    while (std::getline(ls, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

// One small sweep of the seed, read by the checks below (one test: under
// ctest each test is a process of its own, and would run the sweep again).
struct SeedSweepRun {
  TempDir dir;
  RunResult result;
};
const SeedSweepRun& seed_sweep() {
  static SeedSweepRun run;  // destroyed at exit, and its directory with it
  static const bool ran = [] {
    // A few rows: the grid itself is checked by SweepGrid below.
    run.result = run_marchstudio({"sweep", scene("seed"), "--size", "96x54", "--frames", "1", "--rounds", "2",
                                  "--warmup", "0", "--time-by", "cpu", "--ref-spp", "4", "--only",
                                  "textbook,fast,balanced,reference,omega=1.5,tol=fp1,no-bounds,ao=3", "-q", "-o",
                                  run.dir.path().string()});
    return true;
  }();
  (void)ran;
  return run;
}

void WritesCsvJsonAndPlotThatAgree() {
  ASSERT_EQ(seed_sweep().result.exit_code, 0) << seed_sweep().result.err;
  EXPECT_EQ(seed_sweep().result.err, "");  // -q
  const json j = json::parse(read_file(seed_sweep().dir / "seed.sweep.json"));
  EXPECT_EQ(j.at("schema"), "marchstudio.sweep/1");
  EXPECT_EQ(j.at("settings").at("width"), 96);
  EXPECT_EQ(j.at("default_preset"), "balanced");
  EXPECT_EQ(j.at("settings").at("time_by"), "cpu");
  EXPECT_EQ(j.at("settings").at("specialize"), "folded");  // the shader render and bench build
  EXPECT_FALSE(j.at("machine").at("gl_renderer").get<std::string>().empty());
  // The reference settings are in the output.
  const json& ref = j.at("references");
  EXPECT_EQ(ref.at("same_spp").at("spp"), 1);
  EXPECT_EQ(ref.at("supersampled").at("spp"), 4);
  EXPECT_EQ(ref.at("same_spp").at("quality").at("omega"), 1.0);
  EXPECT_GE(ref.at("same_spp").at("quality").at("max_steps").get<int>(), 1000);
  EXPECT_EQ(ref.at("exact").at("status"), "available");  // the seed is a sphere and a plane

  const auto csv = read_csv(read_file(seed_sweep().dir / "seed.sweep.csv"));
  const json& rows = j.at("rows");
  ASSERT_EQ(csv.size(), rows.size() + 1);
  const std::vector<std::string>& header = csv[0];
  for (const auto& line : csv) EXPECT_EQ(line.size(), header.size());
  std::set<std::string> names;
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(csv[i + 1][0], rows[i].at("name").get<std::string>());
    names.insert(rows[i].at("name").get<std::string>());
    const json& t = rows[i].at("time_ms");
    EXPECT_GT(t.at("wall").get<double>(), 0.0);
    EXPECT_GT(t.at("cpu").get<double>(), 0.0);
    EXPECT_EQ(t.at("front").get<double>(), t.at("cpu").get<double>()) << "--time-by cpu";
    EXPECT_LE(t.at("wall").get<double>(), t.at("wall_median_all").get<double>() + 1e-9) << "best round <= all";
  }
  EXPECT_EQ(names.size(), rows.size()) << "row names must be unique";
  for (const char* n : {"textbook", "fast", "balanced", "reference"}) EXPECT_TRUE(names.count(n)) << n;
  EXPECT_EQ(rows.size(), 8u);  // --only

  const Image plot = read_image(seed_sweep().dir / "seed.sweep.png");
  EXPECT_GT(plot.width, 500);
  EXPECT_GT(plot.height, 300);
  EXPECT_NE(seed_sweep().result.out.find("textbook"), std::string::npos) << seed_sweep().result.out;
}

void ReferenceRowHasZeroErrorAgainstItself() {
  ASSERT_EQ(seed_sweep().result.exit_code, 0) << seed_sweep().result.err;
  const json j = json::parse(read_file(seed_sweep().dir / "seed.sweep.json"));
  bool found = false;
  for (const json& r : j.at("rows")) {
    const json& e = r.at("error").at("same_spp");
    if (r.at("name") == "reference") {
      found = true;
      EXPECT_TRUE(e.at("psnr").is_null()) << "identical images have PSNR +inf, written as null";
      EXPECT_EQ(e.at("mae").get<double>(), 0.0);
      EXPECT_EQ(e.at("depth_mean").get<double>(), 0.0);
      EXPECT_EQ(e.at("depth_max").get<double>(), 0.0);
      EXPECT_EQ(e.at("misclassified").get<double>(), 0.0);
      EXPECT_TRUE(r.at("pareto").at("same_spp").get<bool>());
      // Against exact intersection the converged reference is close: the
      // depth where every sample of both hit, within a few tolerances.
      EXPECT_LT(r.at("error").at("exact").at("misclassified").get<double>(), 0.01);
    } else {
      EXPECT_FALSE(e.at("psnr").is_null()) << r.at("name") << " is identical to the reference?";
      EXPECT_GT(e.at("mae").get<double>(), 0.0) << r.at("name");
    }
  }
  EXPECT_TRUE(found);
}

void TextbookIsSlowerInStepsAndWorseThanBalanced() {
  ASSERT_EQ(seed_sweep().result.exit_code, 0) << seed_sweep().result.err;
  const json j = json::parse(read_file(seed_sweep().dir / "seed.sweep.json"));
  json textbook, balanced;
  for (const json& r : j.at("rows")) {
    if (r.at("name") == "textbook") textbook = r;
    if (r.at("name") == "balanced") balanced = r;
  }
  ASSERT_FALSE(textbook.is_null() || balanced.is_null());
  // Deterministic figures only (times are not tested): steps and error.
  EXPECT_GT(textbook.at("cost").at("mean_steps").get<double>(), 10 * balanced.at("cost").at("mean_steps").get<double>());
  EXPECT_EQ(textbook.at("quality").at("hit_tolerance"), 0.0);
  EXPECT_FALSE(textbook.at("quality").at("bounds").get<bool>());
  EXPECT_FALSE(textbook.at("quality").at("analytic_planes").get<bool>());
}

// The exact-intersection image (sdf_shaders/exact.glsl): every row has its
// PSNR against it, converged tracing comes closest, and the default preset
// is well above the textbook tracer and the 40 dB of docs/speed-vs-error.md.
void EveryRowIsComparedWithItsExactImage() {
  ASSERT_EQ(seed_sweep().result.exit_code, 0) << seed_sweep().result.err;
  const json j = json::parse(read_file(seed_sweep().dir / "seed.sweep.json"));
  std::map<std::string, double> psnr;
  for (const json& r : j.at("rows")) {
    const json& x = r.at("error").at("exact");
    ASSERT_TRUE(x.is_object()) << r.at("name");
    ASSERT_FALSE(x.at("psnr").is_null()) << r.at("name") << ": identical to its exact image?";
    EXPECT_GT(x.at("mae").get<double>(), 0.0) << r.at("name");
    psnr[r.at("name").get<std::string>()] = x.at("psnr").get<double>();
  }
  for (const auto& [name, p] : psnr)
    if (name != "reference") EXPECT_GT(psnr.at("reference"), p) << name;
  EXPECT_GT(psnr.at("balanced"), psnr.at("textbook") + 10.0);
  EXPECT_GT(psnr.at("balanced"), 40.0);
  const auto csv = read_csv(read_file(seed_sweep().dir / "seed.sweep.csv"));
  EXPECT_NE(std::find(csv[0].begin(), csv[0].end(), "exact_psnr"), csv[0].end());
}

TEST(SeedSweep, OutputsAgreeAndTheErrorsHold) {
  for (auto [name, check] : {std::pair{"outputs agree", &WritesCsvJsonAndPlotThatAgree},
                             std::pair{"reference row", &ReferenceRowHasZeroErrorAgainstItself},
                             std::pair{"textbook vs balanced", &TextbookIsSlowerInStepsAndWorseThanBalanced},
                             std::pair{"exact images", &EveryRowIsComparedWithItsExactImage}}) {
    SCOPED_TRACE(name);
    check();
  }
}

// exact.glsl's intersections against the tests' own, in double: the depth
// AOV of an exact render of the seed (its one sphere given by hand).
TEST(SweepExact, TheExactImageHitsWhereTheCpuDoes) {
  constexpr int W = 64, H = 36;
  TempDir dir;
  const RunResult r = run_marchstudio({"render", scene("seed"), "-o", (dir / "x.exr").string(), "--size",
                                       std::to_string(W) + "x" + std::to_string(H), "--aov", "depth,steps", "-D",
                                       "EXACT_SPHERES=1", "-D", "EXACT_SPHERE_LIST=vec4(0.0, 1.0, 0.0, 1.0)", "-D",
                                       "EXACT_SPHERE_MATERIALS=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "x.exr");
  const auto ch = [&](const char* n) {
    return static_cast<int>(std::find(img.channels.begin(), img.channels.end(), n) - img.channels.begin());
  };
  const Scene seed = load_scene(scene("seed"));
  int hits = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const ExactHit e = exact_seed_hit(cpu_camera_ray(seed.camera, W, H, x, y), seed.quality.max_distance);
      ASSERT_EQ(img.at(x, y, ch("hit")) > 0.5f, e.hit) << x << "," << y;
      EXPECT_EQ(img.at(x, y, ch("steps")), 0.0f) << "nothing is marched";
      if (e.hit) EXPECT_NEAR(img.at(x, y, ch("Z")), e.t, 2e-6 * (1.0 + e.t)) << x << "," << y;
      hits += e.hit;
    }
  EXPECT_GT(hits, W * H / 3);
}

TEST(Sweep, SceneWithoutExactReferenceSaysWhy) {
  TempDir dir;
  const RunResult r =
      run_marchstudio({"sweep", scene("stilllife"), "--size", "32x18", "--frames", "1", "--warmup", "0", "--ref-spp",
                       "2", "--only", "textbook,balanced", "-q", "-o", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_file(dir / "stilllife.sweep.json"));
  EXPECT_EQ(j.at("rows").size(), 2u);  // --only
  const std::string status = j.at("references").at("exact").at("status");
  EXPECT_NE(status, "available");
  EXPECT_FALSE(status.empty());
  for (const json& row : j.at("rows")) EXPECT_TRUE(row.at("error").at("exact").is_null());
}

// A graph scene sweeps its pruning grid's cell size: half and twice the
// planned cells, on the interpreter with the grid; pruning is exact, so
// every cell size gives the balanced row's image. With --no-prune there is
// no cell-size axis (every cell holds the whole graph).
TEST(Sweep, AGraphSceneGetsACellSizeAxis) {
  TempDir dir;
  const std::string part = (source_dir() / "tests/data/graph/part.toml").string();
  const std::vector<std::string> common = {"sweep", part, "--size", "32x18", "--frames", "1", "--warmup", "0",
                                           "--ref-spp", "2", "--graph-eval", "interpreter", "-q", "-o",
                                           dir.path().string()};
  std::vector<std::string> args = common;
  args.insert(args.end(), {"--only", "balanced,cell=0.5x,cell=2x"});
  const RunResult r = run_marchstudio(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_file(dir / "part.sweep.json"));
  ASSERT_EQ(j.at("rows").size(), 3u);
  std::map<std::string, json> rows;
  for (const json& row : j.at("rows")) rows[row.at("name")] = row;
  const double half = rows.at("cell=0.5x").at("cell_size"), twice = rows.at("cell=2x").at("cell_size");
  EXPECT_EQ(rows.at("balanced").at("cell_size"), 0.0);
  EXPECT_GT(half, 0.0);
  EXPECT_NEAR(twice, 4.0 * half, 1e-5 * twice);
  EXPECT_EQ(rows.at("cell=2x").at("axis"), "cell_size");
  for (const char* n : {"cell=0.5x", "cell=2x"}) {
    EXPECT_EQ(rows.at(n).at("error").at("same_spp").at("psnr"), rows.at("balanced").at("error").at("same_spp").at("psnr"))
        << n;
    EXPECT_EQ(rows.at(n).at("cost").at("mean_steps"), rows.at("balanced").at("cost").at("mean_steps")) << n;
  }
  args = common;
  args.insert(args.end(), {"--no-prune", "--only", "cell=2x"});
  const RunResult np = run_marchstudio(args);
  EXPECT_EQ(np.exit_code, 2) << "no grid, no cell-size rows: " << np.err;
}

TEST(Sweep, BadInputExitsTwo) {
  TempDir dir;
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--grid", "huge"}, {"--frames", "0"}, {"--size", "0x10"}, {"--ref-spp", "2000"},
        {"--preset", "fastest"}, {"--only", "balanced,nonsense"}, {"--time-by", "sundial"}, {"--rounds", "0"}}) {
    std::vector<std::string> args = {"sweep", scene("seed"), "-q", "-o", dir.path().string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 2) << extra[0] << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const RunResult st = run_marchstudio(
      {"sweep", (source_dir() / "tests/data/shader/shadertoy/ok.glsl").string(), "-q", "-o", dir.path().string()});
  EXPECT_EQ(st.exit_code, 2) << st.err;
  EXPECT_TRUE(dir.entries().empty()) << "bad input leaves nothing behind";
}

TEST(SweepGrid, CoversEveryAxisWithoutRepeats) {
  const Scene seed = load_scene(scene("seed"));
  const auto quick = sweep_grid(seed.quality, SweepGrid::quick);
  const auto full = sweep_grid(seed.quality, SweepGrid::full);
  EXPECT_GT(full.size(), quick.size() + 20);
  EXPECT_LT(full.size(), 120u) << "a full sweep must stay a few minutes on llvmpipe";
  EXPECT_EQ(quick[0].name, "textbook");
  const Quality& t = quick[0].quality;
  EXPECT_EQ(t.max_steps, 255);
  EXPECT_EQ(t.hit_tolerance, 0.0f);
  EXPECT_EQ(t.hit_epsilon, 1e-4f);
  EXPECT_EQ(t.max_distance, 100.0f);
  EXPECT_EQ(t.omega, 1.0f);
  EXPECT_FALSE(t.bounds || t.analytic_planes);
  std::set<std::string> names;
  for (const SweepConfig& c : full) EXPECT_TRUE(names.insert(c.name).second) << c.name;
  EXPECT_THROW(parse_sweep_grid("medium"), Error);
  // Every axis of the issue is in the quick grid.
  std::set<std::string> axes;
  for (const SweepConfig& c : quick) axes.insert(c.axis);
  for (const char* a : {"preset", "max_steps", "tolerance", "omega", "geometry", "max_distance", "shadow", "ao_taps",
                        "bounces", "normal_eps"})
    EXPECT_TRUE(axes.count(a)) << a;
}

TEST(SweepGrid, BaselineAndReferenceIgnoreTheScenesTracerKeys) {
  Quality scene_q;
  scene_q.max_steps = 40;
  scene_q.ao_taps = 7;
  scene_q.explicit_keys = {"max_steps", "ao_taps"};
  EXPECT_EQ(sweep_preset_quality(scene_q, "textbook").max_steps, 255);
  EXPECT_EQ(sweep_preset_quality(scene_q, "textbook").ao_taps, 7);  // shading stays the scene's
  EXPECT_EQ(sweep_preset_quality(scene_q, "balanced").max_steps, 40);
}

TEST(SweepPareto, MarksTheRowsNoOtherBeats) {
  SweepResult r;
  auto row = [&](const char* name, double ms, double psnr) {
    SweepRow x;
    x.config.name = name;
    x.gpu_best_median = ms;
    x.same_spp.psnr = psnr;
    x.supersampled.psnr = psnr;
    r.rows.push_back(x);
  };
  row("fast-bad", 1, 20);
  row("slow-bad", 5, 20);   // beaten by fast-bad
  row("mid", 2, 30);
  row("ref", 10, INFINITY);
  row("tie", 2, 30);        // equal to mid: neither beats the other
  mark_pareto(r);
  std::vector<bool> want = {true, false, true, true, true};
  for (size_t i = 0; i < want.size(); ++i) EXPECT_EQ(r.rows[i].pareto_same_spp, want[i]) << r.rows[i].config.name;
}

TEST(SweepExact, RecognisesUnionsOfConstantSpheresOnly) {
  std::vector<Material> mats(2);
  mats[0].name = "floor";
  mats[1].name = "Ball";
  std::string why;
  const auto one = parse_sphere_map(read_file(source_dir() / "scenes/seed.glsl"), mats, &why);
  ASSERT_TRUE(one) << why;
  ASSERT_EQ(one->size(), 1u);
  EXPECT_EQ((*one)[0].center, glm::dvec3(0.0, 1.0, 0.0));
  EXPECT_EQ((*one)[0].radius, 1.0);
  EXPECT_EQ((*one)[0].material, 1);
  const auto two = parse_sphere_map(
      "// two\nvec2 map(vec3 p) {\n  vec2 a = vec2(sdSphere(p, 0.5), MAT_FLOOR); /* origin */\n"
      "  vec2 b = vec2(sdSphere(p - vec3(-1.0, 2.5e0, 3.), 2.0), MAT_BALL);\n  return opUnion(a, b);\n}\n",
      mats, &why);
  ASSERT_TRUE(two) << why;
  ASSERT_EQ(two->size(), 2u);
  EXPECT_EQ((*two)[1].center, glm::dvec3(-1.0, 2.5, 3.0));
  for (const char* bad : {
           "vec2 map(vec3 p) { return vec2(sdBox(p, vec3(1.0)), MAT_BALL); }",
           "vec2 map(vec3 p) { return vec2(sdSphere(p - vec3(0.0, uTime, 0.0), 1.0), MAT_BALL); }",
           "vec2 map(vec3 p) { return vec2(sdSphere(p, 1.0), MAT_NOPE); }",
           "float k = 2.0; vec2 map(vec3 p) { return vec2(sdSphere(p, k), MAT_BALL); }",
           "vec2 map(vec3 p) { return opSmoothUnion(vec2(sdSphere(p, 1.0), MAT_BALL), vec2(sdSphere(p, 2.0), MAT_BALL), 0.1); }",
       }) {
    why.clear();
    EXPECT_FALSE(parse_sphere_map(bad, mats, &why)) << bad;
    EXPECT_FALSE(why.empty()) << bad;
  }
  const Scene columns = load_scene(scene("columns"));
  EXPECT_FALSE(exact_reference(columns, 8, 8, 100.0, &why));
}

// The exact reference's camera and intersections against the tests' own
// (tests/cli/cpu_tracer.h), pixel by pixel.
TEST(SweepExact, AgreesWithTheTestsCpuIntersection) {
  constexpr int W = 48, H = 27;
  const Scene seed = load_scene(scene("seed"));
  std::string why;
  const auto x = exact_reference(seed, W, H, 100.0, &why);
  ASSERT_TRUE(x) << why;
  int hits = 0;
  for (int y = 0; y < H; ++y)
    for (int px = 0; px < W; ++px) {
      const ExactHit e = exact_seed_hit(cpu_camera_ray(seed.camera, W, H, px, y), 100.0);
      const size_t i = static_cast<size_t>(y) * W + px;
      ASSERT_EQ(static_cast<bool>(x->hit[i]), e.hit) << px << "," << y;
      if (e.hit) EXPECT_NEAR(x->t[i], e.t, 1e-5 * e.t) << px << "," << y;
      hits += e.hit;
    }
  EXPECT_GT(hits, W * H / 3);
  EXPECT_LT(hits, W * H);
}

}  // namespace
}  // namespace ms::test
