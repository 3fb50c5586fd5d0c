// Suite files (suite/suite.h): every key, relative paths, globs and backend
// lists, [defaults], and each mistake as one file:line:key error with a
// did-you-mean, as scene files give. No GL.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "suite/outcome.h"
#include "suite/suite.h"
#include "core/error.h"
#include "minimal_suite.h"

namespace ms {
namespace {
namespace fs = std::filesystem;
using test::kMinimalSuite;

const fs::path kSource = MARCH_SOURCE_DIR;
// As if the suite sat in tests/: "../scenes/x.toml" names a shipped scene.
const fs::path kSuite = kSource / "tests" / "suite.toml";

Suite parse(const std::string& text) { return parse_suite(text, kSuite); }

ErrorInfo error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}


TEST(SuiteLoad, TheMinimalCaseReadsAsWritten) {
  const Suite s = parse(kMinimalSuite);
  ASSERT_EQ(s.cases.size(), 1u);
  const SuiteCase& c = s.cases[0];
  EXPECT_EQ(s.name, "suite");
  EXPECT_EQ(c.name, "seed");
  EXPECT_EQ(c.input, kSource / "tests/scenes/seed.toml");  // relative to the suite file
  EXPECT_EQ(c.reference, kSource / "tests/refs/seed.png");
  EXPECT_EQ(c.width, 160);
  EXPECT_EQ(c.height, 90);
  ASSERT_EQ(c.checks.size(), 1u);
  EXPECT_EQ(c.checks[0].metric, Metric::psnr);
  EXPECT_EQ(c.checks[0].threshold, 40.0);
  EXPECT_FALSE(c.checks[0].warn);
  EXPECT_STREQ(backend_name(c.backend), "auto");
  EXPECT_EQ(c.line, 1);
  EXPECT_FALSE(c.cost || c.time_budget || c.frames || c.deterministic);
}

TEST(SuiteLoad, WithoutAThresholdTheImagesMustMatchExactly) {
  const Suite s = parse("[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\n");
  ASSERT_EQ(s.cases[0].checks.size(), 1u);
  EXPECT_EQ(s.cases[0].name, "a");  // the input's stem
  EXPECT_EQ(s.cases[0].checks[0].threshold, default_threshold(Metric::psnr));
}

TEST(SuiteLoad, EveryKey) {
  const Suite s = parse(
      "[suite]\nname = \"mine\"\ncalibration = \"c\"\nclock = \"wall\"\n"
      "[[case]]\nname = \"c\"\nshader = \"toy.glsl\"\nreference = \"out/c_%03d.exr\"\nframes = \"2..4\"\nfps = 30\n"
      "spp = 4\nbackend = \"osmesa\"\nrenderer = \"llvmpipe\"\ndeterministic = true\nspecialize = false\n"
      "metric = \"max\"\nthreshold = 0.02\nwarn = 0.01\npixel_threshold = 0.5\n"
      "[[case.check]]\nmetric = \"fraction\"\nthreshold = 0.1\n"
      "[case.frame_time]\nmax_ratio = 2\nwarn_ratio = 1.5\nframes = 4\nrounds = 2\nwarmup = 0\n"
      "[[case]]\nname = \"d\"\nscene = \"d.toml\"\ntime = 1.5\nframe = 7\npreset = \"fast\"\n"
      "disable = [\"ao\", \"shadows\"]\ndefines = { RADIUS = \"0.5\", TAPS = 3 }\nallow_include = \".\"\n"
      "[case.cost]\nmean_primary_steps = 10\np99_primary_steps = 90\nmean_map_calls = 60\np99_map_calls = 300\n"
      "step_cap_fraction = 0.001\nmax_slack = 1.25\n");
  EXPECT_EQ(s.name, "mine");
  EXPECT_EQ(s.calibration, "c");
  EXPECT_EQ(s.clock, SuiteClock::wall);
  ASSERT_EQ(s.cases.size(), 2u);
  const SuiteCase& c = s.cases[0];
  ASSERT_TRUE(c.frames);
  EXPECT_EQ(c.frames->first, 2);
  EXPECT_EQ(c.frames->second, 4);
  EXPECT_EQ(c.fps, 30.0);
  EXPECT_EQ(c.spp, 4);
  EXPECT_STREQ(backend_name(c.backend), "osmesa");
  EXPECT_EQ(c.renderer, "llvmpipe");
  EXPECT_TRUE(c.deterministic);
  EXPECT_FALSE(c.specialize);
  ASSERT_EQ(c.checks.size(), 2u);
  EXPECT_EQ(c.checks[0].metric, Metric::max);
  EXPECT_EQ(*c.checks[0].warn, 0.01);
  EXPECT_EQ(c.checks[0].pixel_threshold, 0.5f);
  EXPECT_EQ(c.checks[1].metric, Metric::fraction);
  ASSERT_TRUE(c.time_budget);
  EXPECT_EQ(c.time_budget->max_ratio, 2.0);
  EXPECT_EQ(*c.time_budget->warn_ratio, 1.5);
  EXPECT_EQ(c.time_budget->frames, 4);
  EXPECT_EQ(c.time_budget->rounds, 2);
  EXPECT_EQ(c.time_budget->warmup, 0);
  const SuiteCase& d = s.cases[1];
  EXPECT_EQ(*d.time, 1.5f);
  EXPECT_EQ(d.frame, 7);
  EXPECT_EQ(d.preset, "fast");
  EXPECT_EQ(d.disable, (std::vector<std::string>{"ao", "shadows"}));
  EXPECT_EQ(d.defines, (std::vector<std::pair<std::string, std::string>>{{"RADIUS", "0.5"}, {"TAPS", "3"}}));
  ASSERT_EQ(d.allow_include.size(), 1u);
  EXPECT_TRUE(d.checks.empty());  // no reference: a cost-only case
  ASSERT_TRUE(d.cost);
  EXPECT_EQ(*d.cost->mean_primary_steps, 10.0);
  EXPECT_EQ(*d.cost->p99_primary_steps, 90.0);
  EXPECT_EQ(*d.cost->mean_map_calls, 60.0);
  EXPECT_EQ(*d.cost->p99_map_calls, 300.0);
  EXPECT_EQ(*d.cost->step_cap_fraction, 0.001);
  EXPECT_EQ(*d.cost->max_slack, 1.25);
}

TEST(SuiteLoad, DefaultsApplyKeyByKeyAndCasesOverrideThem) {
  const Suite s = parse(
      "[defaults]\nsize = [32, 18]\nthreshold = 50\n[defaults.cost]\nmax_slack = 1.5\nstep_cap_fraction = 0\n"
      "[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\n[case.cost]\nmean_primary_steps = 4\n"
      "[[case]]\nscene = \"b.toml\"\nreference = \"b.png\"\nsize = [8, 8]\nthreshold = 70\n");
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[0].width, 32);
  EXPECT_EQ(s.cases[0].checks[0].threshold, 50.0);
  EXPECT_EQ(*s.cases[0].cost->mean_primary_steps, 4.0);  // its own
  EXPECT_EQ(*s.cases[0].cost->max_slack, 1.5);          // from [defaults.cost]
  EXPECT_EQ(*s.cases[0].cost->step_cap_fraction, 0.0);
  EXPECT_EQ(s.cases[1].width, 8);
  EXPECT_EQ(s.cases[1].checks[0].threshold, 70.0);
  EXPECT_EQ(*s.cases[1].cost->step_cap_fraction, 0.0);  // every case inherits [defaults.cost]
}

TEST(SuiteLoad, AGlobAndABackendListMakeOneCaseEach) {
  const Suite s = parse(
      "[[case]]\nname = \"{name}.{backend}\"\nscene = \"../scenes/s*.toml\"\nexclude = [\"seed\"]\n"
      "backend = [\"egl\", \"osmesa\"]\nreference = \"golden/{name}.png\"\n");
  std::vector<std::string> names;
  for (const SuiteCase& c : s.cases) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"stilllife.egl", "stilllife.osmesa"}));
  EXPECT_EQ(s.cases[1].input, kSource / "scenes/stilllife.toml");
  EXPECT_STREQ(backend_name(s.cases[1].backend), "osmesa");
  EXPECT_EQ(s.cases[1].reference, kSource / "tests/golden/stilllife.png");
}

TEST(SuiteSelect, OnlyTakesGlobsAndRefusesOnesThatMatchNothing) {
  const Suite s = parse("[[case]]\nname = \"{name}.{backend}\"\nscene = \"../scenes/s*.toml\"\n"
                        "backend = [\"egl\", \"osmesa\"]\nreference = \"{name}.png\"\n");
  EXPECT_EQ(select_cases(s, {}).size(), s.cases.size());
  const auto egl = select_cases(s, {"*.egl"});
  ASSERT_EQ(egl.size(), 2u);
  EXPECT_EQ(egl[0]->name, "seed.egl");
  EXPECT_EQ(select_cases(s, {"seed.*", "stilllife.egl"}).size(), 3u);
  try {
    select_cases(s, {"sed.*"});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().key, "--only");
    EXPECT_EQ(e.code(), Exit::bad_input);
  }
}

struct Bad {
  const char* name;
  std::string text;
  int line;
  std::string key;   // exact
  std::string what;  // substring
  std::string hint;  // substring; "" = any
};

class SuiteError : public ::testing::TestWithParam<Bad> {};

TEST_P(SuiteError, NamesFileLineAndKey) {
  const Bad& b = GetParam();
  const ErrorInfo e = error_of(b.text);
  EXPECT_EQ(e.code, Exit::bad_input);
  EXPECT_EQ(e.file, kSuite.string());
  EXPECT_EQ(e.line, b.line) << format_error(e);
  EXPECT_EQ(e.key, b.key) << format_error(e);
  EXPECT_NE(e.what.find(b.what), std::string::npos) << format_error(e);
  EXPECT_NE(e.hint.find(b.hint), std::string::npos) << format_error(e);
  EXPECT_EQ(format_error(e).find('\n'), std::string::npos);
}

const std::string M = kMinimalSuite;  // lines 1-7

INSTANTIATE_TEST_SUITE_P(
    All, SuiteError,
    ::testing::Values(
        Bad{"CaseKeyTypo", M + "treshold = 3\n", 8, "case[0].treshold", "unknown key", "did you mean 'threshold'?"},
        Bad{"KeyOfAnotherTable", M + "max_ratio = 2\n", 8, "case[0].max_ratio", "unknown key",
            "'max_ratio' belongs in [case.frame_time]"},
        Bad{"TopLevelTypo", "[[cases]]\nscene = \"a.toml\"\n", 1, "cases", "unknown key", "did you mean 'case'?"},
        Bad{"SuiteKeyTypo", "[suite]\ncalibraton = \"x\"\n" + M, 2, "suite.calibraton", "unknown key",
            "did you mean 'calibration'?"},
        Bad{"CheckKeyTypo", M + "[[case.check]]\nmetirc = \"max\"\n", 9, "case[0].check[0].metirc", "unknown key",
            "did you mean 'metric'?"},
        Bad{"CostKeyTypo", M + "[case.cost]\nmean_primary_step = 3\n", 9, "case[0].cost.mean_primary_step",
            "unknown key", "did you mean 'mean_primary_steps'?"},
        Bad{"TimeKeyTypo", "[suite]\ncalibration = \"seed\"\n" + M + "[case.frame_time]\nmax_ration = 2\n", 11,
            "case[0].frame_time.max_ration", "unknown key", "did you mean 'max_ratio'?"},
        Bad{"DefaultsTakeNoName", "[defaults]\nname = \"x\"\n" + M, 2, "defaults.name", "unknown key", ""},
        Bad{"MetricTypo", "[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\nmetric = \"psrn\"\n", 4,
            "case[0].metric", "unknown value 'psrn'", "did you mean 'psnr'?"},
        Bad{"BackendTypo", M + "backend = \"elg\"\n", 8, "case[0].backend", "unknown value 'elg'",
            "did you mean 'egl'?"},
        Bad{"EffectTypo", M + "disable = [\"a0\"]\n", 8, "case[0].disable", "unknown value 'a0'", "did you mean 'ao'?"},
        Bad{"PresetTypo", M + "preset = \"balnced\"\n", 8, "case[0].preset", "unknown value 'balnced'",
            "did you mean 'balanced'?"},
        Bad{"SizeOneNumber", "[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\nsize = [160]\n", 4, "case[0].size",
            "an array of 2 integers", "size = [160, 90]"},
        Bad{"SizeZero", "[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\nsize = [0, 9]\n", 4, "case[0].size",
            "in [1, 16384]", ""},
        Bad{"ThresholdNan", "[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\nthreshold = nan\n", 4,
            "case[0].threshold", "finite", ""},
        Bad{"MaxThresholdNegative", "[[case]]\nscene = \"a.toml\"\nreference = \"a.png\"\nmetric = \"max\"\nthreshold = -1\n",
            5, "case[0].threshold", ">= 0", ""},
        Bad{"WarnPastThreshold", M + "warn = 30\n", 8, "case[0].warn", "past the threshold", "warn >= threshold"},
        Bad{"NoInput", "[[case]]\nname = \"x\"\nreference = \"a.png\"\n", 1, "case[0]", "needs 'scene' or 'shader'", ""},
        Bad{"BothInputs", "[[case]]\nscene = \"a.toml\"\nshader = \"a.glsl\"\n", 3, "case[0]", "exclude each other", ""},
        Bad{"ChecksNothing", "[[case]]\nscene = \"a.toml\"\n", 1, "case[0]", "checks nothing", "reference"},
        Bad{"MetricWithoutReference", "[[case]]\nscene = \"a.toml\"\nmetric = \"max\"\n", 3, "case[0].reference",
            "need a 'reference'", ""},
        Bad{"ReferenceExtension", "[[case]]\nscene = \"a.toml\"\nreference = \"a.gif\"\n", 3, "case[0].reference",
            "unknown image extension", ""},
        Bad{"FlipOnExr", "[[case]]\nscene = \"a.toml\"\nreference = \"a.exr\"\nmetric = \"flip\"\n", 3,
            "case[0].reference", "flip compares display images", ".png"},
        Bad{"FramesWithoutPattern", "[[case]]\nshader = \"a.glsl\"\nreference = \"a.png\"\nframes = [0, 3]\n", 3,
            "case[0].reference", "frame field", ""},
        Bad{"PatternWithoutFrames", "[[case]]\nshader = \"a.glsl\"\nreference = \"a_%02d.png\"\n", 3,
            "case[0].reference", "no 'frames'", ""},
        Bad{"FramesBackwards", "[[case]]\nshader = \"a.glsl\"\nreference = \"a%d.png\"\nframes = [5, 3]\n", 4,
            "case[0].frames", "ends before it starts", ""},
        Bad{"DuplicateName", M + M, 8, "case[1].name", "duplicate case name 'seed'", "line 1"},
        Bad{"GlobWithoutName", "[[case]]\nname = \"x\"\nscene = \"../scenes/*.toml\"\nreference = \"a.png\"\n", 2,
            "case[0].name", "{name}", ""},
        Bad{"GlobMatchesNothing", "[[case]]\nscene = \"../scenes/*.tmol\"\nreference = \"{name}.png\"\n", 2,
            "case[0].scene", "no file matches", ""},
        Bad{"BackendsWithoutField", M + "backend = [\"egl\", \"osmesa\"]\n", 2, "case[0].name",
            "{backend}", "seed.{backend}"},
        Bad{"UnknownField", "[[case]]\nname = \"{stem}\"\nscene = \"a.toml\"\nreference = \"a.png\"\n", 2,
            "case[0].name", "unknown {field}", "{name}"},
        Bad{"BadCaseName", "[[case]]\nname = \"a b\"\nscene = \"a.toml\"\nreference = \"a.png\"\n", 2, "case[0].name",
            "is not [A-Za-z0-9_.-]", ""},
        Bad{"DefineNotIdentifier", M + "defines = { 1X = \"2\" }\n", 8, "case[0].defines.1X", "not a GLSL identifier",
            ""},
        Bad{"DefineFloat", M + "defines = { R = 0.5 }\n", 8, "case[0].defines.R", "a string or an integer",
            "\"0.5\""},
        Bad{"CostWithoutBound", M + "[case.cost]\nmax_slack = 2\n", 8, "case[0].cost", "sets no bound", ""},
        Bad{"SlackBelowOne", M + "[case.cost]\nmean_primary_steps = 2\nmax_slack = 1\n", 10, "case[0].cost.max_slack",
            "> 1", ""},
        Bad{"TimeWithoutCalibration", M + "[case.frame_time]\nmax_ratio = 2\n", 1, "suite.calibration",
            "need a calibration case", "calibration = "},
        Bad{"TimeWithoutMaxRatio", "[suite]\ncalibration = \"seed\"\n" + M + "[case.frame_time]\nframes = 3\n", 10,
            "case[0].frame_time.max_ratio", "missing required key", "max_ratio = 1.5"},
        Bad{"CalibrationUnknown", "[suite]\ncalibration = \"sed\"\n" + M, 2, "suite.calibration",
            "no case is named 'sed'", "did you mean 'seed'?"},
        Bad{"ClockTypo", "[suite]\nclock = \"cpuu\"\n" + M, 2, "suite.clock", "unknown value", "did you mean 'cpu'?"},
        Bad{"NoCases", "[suite]\nname = \"x\"\n", 0, "case", "no [[case]]", ""},
        Bad{"InvalidToml", "[[case]\n", 1, "", "invalid TOML", ""}),
    [](const ::testing::TestParamInfo<Bad>& i) { return std::string(i.param.name); });

TEST(SuiteLoad, AMissingFileIsBadInputNamingIt) {
  try {
    load_suite(kSource / "tests/no-such-suite.toml");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_EQ(e.info().file, (kSource / "tests/no-such-suite.toml").string());
  }
  EXPECT_THROW(load_suite(kSource / "tests"), Error);  // a directory
}

// The two exit-code conventions (suite/outcome.h).
TEST(Outcome, ExitCodes) {
  EXPECT_EQ(exit_code_for(ExitCodes::standard, Outcome::pass), 0);
  EXPECT_EQ(exit_code_for(ExitCodes::standard, Outcome::warn), 0);
  EXPECT_EQ(exit_code_for(ExitCodes::standard, Outcome::fail), 1);
  EXPECT_EQ(exit_code_for(ExitCodes::standard, Outcome::error, Exit::bad_input), 2);
  EXPECT_EQ(exit_code_for(ExitCodes::standard, Outcome::error, Exit::system), 3);
  EXPECT_EQ(exit_code_for(ExitCodes::idiff, Outcome::pass), 0);
  EXPECT_EQ(exit_code_for(ExitCodes::idiff, Outcome::warn), 1);
  EXPECT_EQ(exit_code_for(ExitCodes::idiff, Outcome::fail), 2);
  EXPECT_EQ(exit_code_for(ExitCodes::idiff, Outcome::error, Exit::system), 4);
  EXPECT_EQ(parse_exit_codes("idiff"), ExitCodes::idiff);
  EXPECT_EQ(parse_exit_codes("default"), ExitCodes::standard);
  EXPECT_THROW(parse_exit_codes("oiio"), Error);
}

TEST(Outcome, WarnLevelsSitOnThePassingSide) {
  CompareMetrics m;
  m.psnr = 45.0;
  m.max_abs = 0.02;
  EXPECT_EQ(classify(m, Metric::psnr, 40.0, 50.0), Outcome::warn);
  EXPECT_EQ(classify(m, Metric::psnr, 40.0, 45.0), Outcome::pass);  // the boundary passes
  EXPECT_EQ(classify(m, Metric::psnr, 46.0, 50.0), Outcome::fail);
  EXPECT_EQ(classify(m, Metric::psnr, 40.0), Outcome::pass);
  EXPECT_EQ(classify(m, Metric::max, 0.03, 0.01), Outcome::warn);
  EXPECT_EQ(classify(m, Metric::max, 0.01, 0.005), Outcome::fail);
  m.nonfinite_b = 1;
  EXPECT_EQ(classify(m, Metric::max, 1.0, 1.0), Outcome::fail);  // NaN/Inf always fail
  EXPECT_TRUE(warn_level_valid(Metric::psnr, 40, 50));
  EXPECT_FALSE(warn_level_valid(Metric::psnr, 40, 30));
  EXPECT_TRUE(warn_level_valid(Metric::mae, 0.1, 0.05));
  EXPECT_FALSE(warn_level_valid(Metric::mae, 0.1, 0.2));
}

}  // namespace
}  // namespace ms
