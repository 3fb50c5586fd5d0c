// `marchstudio test` through the real binary: docs/testing.md's minimal suite
// as written, relative paths, --update and its CI guard, exit codes (default and
// idiff), warn levels, JUnit and JSON, cost and frame-time budgets, frame
// ranges, bad cases among good ones. The HTML report in a real browser is
// test_test_report.cpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>

#include "io/image_io.h"
#include "minimal_suite.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// Sets (or unsets, with nullopt) an environment variable for this scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value->c_str(), 1) : ::unsetenv(name);
  }
  ~ScopedEnv() { old_ ? ::setenv(name_.c_str(), old_->c_str(), 1) : ::unsetenv(name_.c_str()); }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

std::string scene(const std::string& name) { return (source_dir() / "scenes" / (name + ".toml")).string(); }

// A suite directory holding a copy of the seed scene under scenes/, so the
// issue's relative paths work as written.
struct SuiteDir {
  TempDir dir;
  SuiteDir() {
    for (const char* f : {"seed.toml", "seed.glsl"}) write_file(dir / "scenes" / f, read_file(source_dir() / "scenes" / f));
  }
  fs::path suite(const std::string& text, const std::string& name = "suite.toml") {
    write_file(dir / name, text);
    return dir / name;
  }
};

RunResult test_cmd(const fs::path& suite, std::vector<std::string> extra = {}, const fs::path& cwd = {}) {
  std::vector<std::string> args = {"test", suite.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_marchstudio(args, cwd);
}

json json_of(const RunResult& r) {
  try {
    return json::parse(r.out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not JSON: " << e.what() << "\n" << r.out << r.err;
    return json::object();
  }
}


TEST(TestCommand, TheMinimalSuiteWorksAsWrittenFromAnyDirectory) {
  ScopedEnv no_ci("CI", std::nullopt);
  SuiteDir d;
  const fs::path suite = d.suite(kMinimalSuite);
  // No reference yet: the case cannot run, and says how to make one.
  const RunResult none = test_cmd(suite, {}, "/");
  EXPECT_EQ(none.exit_code, 2) << none.out << none.err;
  EXPECT_NE(none.out.find("no reference " + (d.dir / "refs/seed.png").string()), std::string::npos) << none.out;
  EXPECT_NE(none.out.find("--update"), std::string::npos) << none.out;
  EXPECT_FALSE(fs::exists(d.dir / "refs"));

  const RunResult up = test_cmd(suite, {"--update"}, "/");
  EXPECT_EQ(up.exit_code, 0) << up.out << up.err;
  EXPECT_NE(up.out.find("updated 1 reference"), std::string::npos) << up.out;
  EXPECT_NE(up.out.find((d.dir / "refs/seed.png").string() + " (new)"), std::string::npos) << up.out;
  // The reference is exactly what `render` writes for these settings.
  const RunResult render = run_marchstudio({"render", (d.dir / "scenes/seed.toml").string(), "--size", "160x90", "-o",
                                            (d.dir / "render.png").string()});
  ASSERT_EQ(render.exit_code, 0) << render.err;
  EXPECT_EQ(run_marchstudio({"compare", (d.dir / "render.png").string(), (d.dir / "refs/seed.png").string()}).exit_code, 0);

  const RunResult ok = test_cmd(suite, {}, "/");
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("pass  seed"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("psnr inf dB (identical) >= 40.00 dB"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("1 case: 1 passed, 0 warned, 0 failed, 0 could not run"), std::string::npos) << ok.out;
}

TEST(TestCommand, UpdateRefusesInCiUnlessForced) {
  SuiteDir d;
  const fs::path suite = d.suite(kMinimalSuite);
  {
    ScopedEnv ci("CI", "true");
    const RunResult r = test_cmd(suite, {"--update"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--update: refusing to write references with CI set"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d.dir / "refs"));
    const RunResult forced = test_cmd(suite, {"--update", "--force"});
    EXPECT_EQ(forced.exit_code, 0) << forced.out << forced.err;
    EXPECT_TRUE(fs::exists(d.dir / "refs/seed.png"));
  }
  EXPECT_EQ(test_cmd(suite, {"--force"}).exit_code, 2);  // --force alone is a mistake
}

// Two cases against one reference: `same` passes, `moved` (the checker moved
// 1 cm) fails psnr 60 but passes psnr 40 with a warning at 60.
struct TwoCases : ::testing::Test {
  SuiteDir d;
  fs::path suite;
  void SetUp() override {
    ScopedEnv no_ci("CI", std::nullopt);
    const std::string common = "scene = \"scenes/seed.toml\"\nreference = \"refs/seed.png\"\nsize = [64, 36]\n";
    ASSERT_EQ(test_cmd(d.suite("[[case]]\nname = \"same\"\n" + common), {"--update"}).exit_code, 0);
    suite = d.suite("[[case]]\nname = \"same\"\n" + common + "threshold = 60\n[[case]]\nname = \"moved\"\n" + common +
                    "time = 0.05\nthreshold = 60\n");
  }
};

TEST_F(TwoCases, AFailingCaseExitsOneAndReportsItInJunitAndJson) {
  const fs::path junit = d.dir / "junit.xml";
  const RunResult r = test_cmd(suite, {"--junit", junit.string(), "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const json j = json_of(r);
  EXPECT_EQ(j.value("schema", ""), "marchstudio.test/1");
  ASSERT_EQ(j["cases"].size(), 2u);
  EXPECT_EQ(j["cases"][0]["outcome"], "pass");
  EXPECT_EQ(j["cases"][1]["outcome"], "fail");
  EXPECT_LT(j["cases"][1]["checks"][0]["value"].get<double>(), 60.0);
  EXPECT_NE(r.err.find("FAIL  moved"), std::string::npos) << r.err;  // with --json the case lines go to stderr
  const std::string x = read_file(junit);
  EXPECT_NE(x.find("tests=\"2\" failures=\"1\" errors=\"0\""), std::string::npos) << x;
  EXPECT_NE(x.find("<testcase name=\"moved\""), std::string::npos) << x;
  EXPECT_NE(x.find("<failure message=\"psnr "), std::string::npos) << x;
  EXPECT_NE(x.find("&lt; 60.00 dB\" type=\"threshold\">"), std::string::npos) << x;
  EXPECT_EQ(test_cmd(suite, {"--exit-codes", "idiff"}).exit_code, 2);
  EXPECT_EQ(test_cmd(suite, {"--only", "same"}).exit_code, 0);
}

TEST_F(TwoCases, AWarnLevelPassesByDefaultAndIsOneForIdiff) {
  const fs::path warned = d.suite(read_file(suite).substr(0, read_file(suite).rfind("threshold = 60")) +
                                      "threshold = 30\nwarn = 60\n",
                                  "warn.toml");
  const RunResult r = test_cmd(warned, {"--only", "moved"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("WARN  moved"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("past the warn level 60.00 dB"), std::string::npos) << r.out;
  EXPECT_EQ(test_cmd(warned, {"--only", "moved", "--exit-codes", "idiff"}).exit_code, 1);
  EXPECT_EQ(test_cmd(warned, {"--only", "same", "--exit-codes", "idiff"}).exit_code, 0);
}

TEST_F(TwoCases, UpdateRewritesOnlyTheFailingReference) {
  ScopedEnv no_ci("CI", std::nullopt);
  // Each case its own reference: `moved` renders something else than its file.
  const std::string common = "scene = \"scenes/seed.toml\"\nsize = [64, 36]\nthreshold = 60\n";
  fs::copy_file(d.dir / "refs/seed.png", d.dir / "refs/moved.png");
  const fs::path own = d.suite("[[case]]\nname = \"same\"\nreference = \"refs/seed.png\"\n" + common +
                                   "[[case]]\nname = \"moved\"\nreference = \"refs/moved.png\"\ntime = 0.05\n" + common,
                               "own.toml");
  const std::string before = read_file(d.dir / "refs/seed.png");
  const auto mtime = fs::last_write_time(d.dir / "refs/seed.png");
  const RunResult r = test_cmd(own, {"--update"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("updated 1 reference"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find((d.dir / "refs/moved.png").string() + " (psnr "), std::string::npos) << r.out;
  EXPECT_EQ(read_file(d.dir / "refs/seed.png"), before);
  EXPECT_EQ(fs::last_write_time(d.dir / "refs/seed.png"), mtime);
  for (const auto& e : fs::directory_iterator(d.dir / "refs"))  // nothing half-written left behind
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
  EXPECT_EQ(test_cmd(own).exit_code, 0);
}

TEST(TestCommand, ABadSuiteIsOneLineNamingFileLineAndKey) {
  SuiteDir d;
  const fs::path suite = d.suite(std::string(kMinimalSuite) + "treshold = 3\n");
  const fs::path junit = d.dir / "j.xml", report = d.dir / "report";
  const RunResult r = test_cmd(suite, {"--junit", junit.string(), "--report", report.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "marchstudio: " + suite.string() +
                       ":8: unknown key 'case[0].treshold' (did you mean 'threshold'?)\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(junit));
  EXPECT_FALSE(fs::exists(report));
  EXPECT_EQ(test_cmd(suite, {"--exit-codes", "idiff"}).exit_code, 4);
  EXPECT_EQ(test_cmd(d.dir / "missing.toml", {"--exit-codes", "idiff"}).exit_code, 4);
  EXPECT_EQ(test_cmd(d.dir / "missing.toml").exit_code, 2);
}

// A case whose input is broken cannot run; the others still do, and every
// report says which is which.
TEST(TestCommand, ABrokenCaseDoesNotStopTheOthers) {
  SuiteDir d;
  std::string typo = read_file(d.dir / "scenes/seed.toml");
  ASSERT_NE(typo.find("spp      = 1"), std::string::npos);
  typo.replace(typo.find("spp      = 1"), 3, "spq");
  write_file(d.dir / "scenes/typo.toml", typo);
  const fs::path suite = d.suite(
      "[[case]]\nname = \"typo\"\nscene = \"scenes/typo.toml\"\n[case.cost]\nmean_primary_steps = 100\n"
      "[[case]]\nname = \"toy\"\nshader = \"" + (source_dir() / "tests/data/shader/shadertoy/ok.glsl").string() +
      "\"\nsize = [16, 9]\n[case.cost]\nmean_primary_steps = 100\n"
      "[[case]]\nname = \"seed\"\nscene = \"scenes/seed.toml\"\nsize = [32, 18]\n[case.cost]\nmean_primary_steps = 100\n");
  const fs::path junit = d.dir / "j.xml";
  const RunResult r = test_cmd(suite, {"--json", "--junit", junit.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const json j = json_of(r);
  ASSERT_EQ(j["cases"].size(), 3u);
  EXPECT_EQ(j["cases"][0]["outcome"], "error");
  EXPECT_NE(j["cases"][0]["message"].get<std::string>().find("typo.toml"), std::string::npos);
  EXPECT_NE(j["cases"][0]["message"].get<std::string>().find("spq"), std::string::npos);
  EXPECT_EQ(j["cases"][1]["outcome"], "error");  // a Shadertoy shader has no step counters
  EXPECT_NE(j["cases"][1]["message"].get<std::string>().find(suite.string() + ":"), std::string::npos);
  EXPECT_EQ(j["cases"][2]["outcome"], "pass");
  EXPECT_NE(read_file(junit).find("errors=\"2\""), std::string::npos);
  EXPECT_EQ(test_cmd(suite, {"--exit-codes", "idiff"}).exit_code, 4);
}

// Cost budgets come from bench's counting pass: the same numbers.
TEST(TestCommand, CostBudgetsAreBenchsCountsAndFailBothWays) {
  SuiteDir d;
  const RunResult b = run_marchstudio({"bench", scene("columns"), "--size", "64x36", "--frames", "1", "--warmup", "0",
                                       "--preset", "fast", "--json"});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const json bench = json::parse(b.out).at("cost");
  const double steps = bench["primary_steps"]["mean"].get<double>();
  auto suite_with = [&](double bound, const std::string& name) {
    return d.suite("[[case]]\nname = \"c\"\nscene = \"" + scene("columns") +
                       "\"\nsize = [64, 36]\npreset = \"fast\"\n[case.cost]\nmean_primary_steps = " + std::to_string(bound) +
                       "\nmax_slack = 1.25\np99_map_calls = " +
                       std::to_string(bench["sdf_evals"]["p99"].get<double>() * 1.1) + "\n",
                   name);
  };
  const RunResult ok = test_cmd(suite_with(steps * 1.1, "ok.toml"), {"--json"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const json cost = json_of(ok)["cases"][0]["cost"];
  EXPECT_EQ(cost["primary_steps"], bench["primary_steps"]);
  EXPECT_EQ(cost["sdf_evals"], bench["sdf_evals"]);
  EXPECT_EQ(cost["step_cap_fraction"], bench["step_cap_fraction"]);
  const RunResult over = test_cmd(suite_with(steps * 0.9, "over.toml"));
  EXPECT_EQ(over.exit_code, 1);
  EXPECT_NE(over.out.find("costs more"), std::string::npos) << over.out;
  const RunResult slack = test_cmd(suite_with(steps * 1.3, "slack.toml"));
  EXPECT_EQ(slack.exit_code, 1);
  EXPECT_NE(slack.out.find("cheaper now, lower the bound"), std::string::npos) << slack.out;
}

// A scene graph's primitive evaluations: bench's figure, bounded both
// ways; on a scene without a graph the key is a one-line input error.
TEST(TestCommand, PrimitiveEvalBudgetsAreBenchsAndNeedAGraph) {
  SuiteDir d;
  const std::string part = (source_dir() / "scenes/part.toml").string();
  const RunResult b = run_marchstudio({"bench", part, "--size", "48x27", "--frames", "1", "--warmup", "0", "--json"});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const double evals = json::parse(b.out).at("cost").at("primitive_evals").at("mean").get<double>();
  ASSERT_GT(evals, 0.0);
  auto suite_with = [&](const std::string& sc, double bound, const std::string& name) {
    return d.suite("[[case]]\nname = \"c\"\nscene = \"" + sc + "\"\nsize = [48, 27]\n[case.cost]\n" +
                       "mean_primitive_evals = " + std::to_string(bound) + "\n",
                   name);
  };
  const RunResult ok = test_cmd(suite_with(part, evals * 1.1, "ok.toml"), {"--json"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err << ok.out;
  EXPECT_NEAR(json_of(ok)["cases"][0]["cost"]["primitive_evals"]["mean"].get<double>(), evals, 1e-6);
  const RunResult over = test_cmd(suite_with(part, evals * 0.9, "over.toml"));
  EXPECT_EQ(over.exit_code, 1);
  EXPECT_NE(over.out.find("mean_primitive_evals"), std::string::npos) << over.out;
  const RunResult plain = test_cmd(suite_with(scene("columns"), 10.0, "plain.toml"));
  EXPECT_NE(plain.exit_code, 0);
  EXPECT_NE((plain.out + plain.err).find("mean_primitive_evals needs a scene graph"), std::string::npos)
      << plain.out << plain.err;
}

// Frame time as a ratio to the calibration case, measured in the same run:
// 16 samples per pixel cost several times one, whatever the machine's load.
TEST(TestCommand, FrameTimeBudgetsAreRatiosToTheCalibrationCase) {
  SuiteDir d;
  const std::string timed = "scene = \"scenes/seed.toml\"\nsize = [96, 54]\n";
  const fs::path suite = d.suite(
      "[suite]\ncalibration = \"one\"\n"
      "[[case]]\nname = \"one\"\n" + timed + "[case.frame_time]\nmax_ratio = 3\nframes = 4\nrounds = 3\n"
      "[[case]]\nname = \"sixteen\"\n" + timed + "spp = 16\n[case.frame_time]\nmax_ratio = 3\nframes = 4\nrounds = 3\n"
      "[[case]]\nname = \"warned\"\n" + timed + "spp = 16\n[case.frame_time]\nmax_ratio = 1000\nwarn_ratio = 3\n"
      "frames = 2\nrounds = 1\n");
  const RunResult r = test_cmd(suite, {"--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const json j = json_of(r);
  ASSERT_EQ(j["cases"].size(), 3u);
  const double same = j["cases"][0]["frame_time"]["ratio"].get<double>();
  const double sixteen = j["cases"][1]["frame_time"]["ratio"].get<double>();
  EXPECT_GT(same, 1.0 / 3) << j["cases"][0].dump();
  EXPECT_LT(same, 3.0) << j["cases"][0].dump();
  EXPECT_EQ(j["cases"][0]["outcome"], "pass");
  EXPECT_GT(sixteen, 4.0) << j["cases"][1].dump();
  EXPECT_EQ(j["cases"][1]["outcome"], "fail");
  EXPECT_EQ(j["cases"][2]["outcome"], "warn");
  EXPECT_EQ(j["cases"][1]["frame_time"]["clock"], "cpu");  // llvmpipe: this process's CPU time
}

// A frame range compares each frame with its own file; a bad frame is named.
TEST(TestCommand, AFrameRangeChecksEveryFrame) {
  ScopedEnv no_ci("CI", std::nullopt);
  SuiteDir d;
  write_file(d.dir / "toy.glsl",
             "void mainImage(out vec4 c, in vec2 f) {\n"
             "  c = vec4(fract(iTime), float(iFrame) / 8.0, f.x / iResolution.x, 1.0);\n}\n");
  const fs::path suite = d.suite("[[case]]\nname = \"toy\"\nshader = \"toy.glsl\"\nsize = [16, 8]\nframes = [0, 2]\n"
                                 "fps = 4\nreference = \"refs/toy_%02d.png\"\nthreshold = 60\ndeterministic = true\n");
  const RunResult up = test_cmd(suite, {"--update"});
  EXPECT_EQ(up.exit_code, 0) << up.out << up.err;
  EXPECT_NE(up.out.find("updated 3 references"), std::string::npos) << up.out;
  // Frame 2 is `render --time 0.5 --frame 2`.
  ASSERT_EQ(run_marchstudio({"render", (d.dir / "toy.glsl").string(), "--size", "16x8", "--time", "0.5", "--frame", "2",
                             "-o", (d.dir / "f2.png").string()})
                .exit_code,
            0);
  EXPECT_EQ(run_marchstudio({"compare", (d.dir / "f2.png").string(), (d.dir / "refs/toy_02.png").string()}).exit_code, 0);
  const RunResult ok = test_cmd(suite, {"--json"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(json_of(ok)["cases"][0]["frames"], 3);
  EXPECT_EQ(json_of(ok)["cases"][0]["deterministic"]["differing_values"], 0);
  fs::copy_file(d.dir / "refs/toy_00.png", d.dir / "refs/toy_01.png", fs::copy_options::overwrite_existing);
  const RunResult bad = test_cmd(suite);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.out.find("at frame 1"), std::string::npos) << bad.out;
}

TEST(TestCommand, BackendListsShareOneProcessAndAreNamed) {
  SuiteDir d;
  const fs::path suite = d.suite("[[case]]\nname = \"{name}.{backend}\"\nscene = \"scenes/seed.toml\"\nsize = [32, 18]\n"
                                 "backend = [\"egl\", \"osmesa\"]\n[case.cost]\nmean_primary_steps = 1000\n");
  const RunResult list = test_cmd(suite, {"--list"});
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.out.find("seed.egl\t"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("seed.osmesa\t"), std::string::npos) << list.out;
  const RunResult r = test_cmd(suite, {"--json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json j = json_of(r);
  ASSERT_EQ(j["machines"].size(), 2u);
  EXPECT_EQ(j["cases"][0]["backend"], "egl-surfaceless");
  EXPECT_EQ(j["cases"][1]["backend"], "osmesa");
  EXPECT_EQ(j["cases"][0]["cost"]["primary_steps"], j["cases"][1]["cost"]["primary_steps"]);
  const RunResult wrong = test_cmd(suite, {"--only", "seed.vulkan"});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("--only"), std::string::npos) << wrong.err;
}

TEST(TestCommand, ARendererItCannotHaveIsASystemFailure) {
  SuiteDir d;
  const fs::path suite = d.suite("[[case]]\nscene = \"scenes/seed.toml\"\nsize = [8, 8]\nrenderer = \"NoSuchGPU\"\n"
                                 "[case.cost]\nmean_primary_steps = 1000\n");
  const RunResult r = test_cmd(suite);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("NoSuchGPU"), std::string::npos) << r.out;
  EXPECT_EQ(test_cmd(suite, {"--exit-codes", "idiff"}).exit_code, 4);
}

// docs/testing.md's table of JSON fields and the output agree both ways:
// every leaf the output has (nulls included, array indices as N) is in the
// table, and every field in the table appears in a run that has them all.
void leaves(const json& j, const std::string& at, std::set<std::string>& out) {
  if (j.is_object() && !j.empty()) {
    for (auto it = j.begin(); it != j.end(); ++it) leaves(it.value(), at + "/" + it.key(), out);
  } else if (j.is_array() && !j.empty()) {
    for (const json& e : j) leaves(e, at + "/N", out);
  } else if (!(j.is_array() || j.is_object())) {
    out.insert(at);
  }
}

TEST(TestCommand, TheJsonFieldsAreThoseDocsTestingMdLists) {
  ScopedEnv no_ci("CI", std::nullopt);
  SuiteDir d;
  const fs::path suite = d.suite(
      "[suite]\ncalibration = \"a\"\n"
      "[[case]]\nname = \"a\"\nscene = \"scenes/seed.toml\"\nsize = [32, 18]\nreference = \"refs/a.png\"\n"
      "threshold = 30\nwarn = 40\ndeterministic = true\n[case.cost]\nmean_primary_steps = 1000\n"
      "[[case]]\nname = \"b\"\nscene = \"scenes/seed.toml\"\nsize = [32, 18]\n"
      "[case.frame_time]\nmax_ratio = 100\nframes = 1\nrounds = 1\n");
  const RunResult r = test_cmd(suite, {"--update", "--json", "--report", (d.dir / "report").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::set<std::string> out;
  leaves(json_of(r), "", out);

  const std::string doc = read_file(source_dir() / "docs/testing.md");
  const size_t from = doc.find("| field | meaning |", doc.find("**`--json`.**"));
  ASSERT_NE(from, std::string::npos);
  const std::string table = doc.substr(from, doc.find("\n\n", from) - from);
  std::set<std::string> documented;
  static const std::regex field("`(/[^`]+)`");
  for (auto it = std::sregex_iterator(table.begin(), table.end(), field); it != std::sregex_iterator(); ++it)
    documented.insert((*it)[1].str());
  for (const std::string& f : out) EXPECT_TRUE(documented.count(f)) << f << " is in the output, not in docs/testing.md";
  for (const std::string& f : documented) EXPECT_TRUE(out.count(f)) << f << " is in docs/testing.md, not in the output";
}

}  // namespace
}  // namespace ms::test
