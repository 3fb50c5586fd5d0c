// A test suite: the cases `marchstudio test SUITE.toml` renders and checks
// (docs/testing.md has every key). Loading checks the whole file first,
// with the scene loader's reading helpers, so a typo is one file:line error
// with a did-you-mean before any GL work. No GL, no rendering here.
//
//   [[case]]
//   name = "seed"
//   scene = "scenes/seed.toml"       # anything `render` takes
//   reference = "refs/seed.png"
//   size = [160, 90]
//   metric = "psnr"
//   threshold = 40
//
//   Suite s = load_suite("tests/suite.toml");   // throws ms::Error (bad_input)
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gl/context.h"
#include "io/compare.h"

namespace ms {

// One image metric against the reference.
struct ImageCheck {
  Metric metric = Metric::psnr;
  double threshold = 0.0;       // default_threshold(metric) when the file gives none: an exact match
  std::optional<double> warn;   // pass, but worse than this, is a warning
  float pixel_threshold = 1.0f / 255.0f;  // for `fraction`
};

// Upper bounds on the counting pass (bench's: one ray per pixel centre,
// the AOV counters), per pixel over all pixels. Unset bounds are not checked.
struct CostBudget {
  std::optional<double> mean_primary_steps, p99_primary_steps;
  std::optional<double> mean_map_calls, p99_map_calls;  // every map() call of the pixel (sdf_evals)
  std::optional<double> step_cap_fraction;
  // A scene graph's primitives evaluated per pixel over every map() call
  // (bench's cost.primitive_evals: a second counting pass).
  std::optional<double> mean_primitive_evals;
  // A step or map-call bound more than this factor above its measurement
  // protects nothing: fail, so an improvement gets its bound lowered.
  std::optional<double> max_slack;
};

// Frame time as a ratio to the suite's calibration case, measured in the
// same process in alternating rounds (so a loaded machine slows both).
struct TimeBudget {
  double max_ratio = 0.0;
  std::optional<double> warn_ratio;
  int frames = 10;  // timed frames per round, each side
  int rounds = 3;   // the ratio is the median of the rounds' ratios
  int warmup = 2;   // untimed frames before each side of each round
};

struct SuiteCase {
  std::string name;                   // unique, [A-Za-z0-9_.-]
  std::filesystem::path input;        // scene .toml or Shadertoy .glsl, resolved against the suite file
  std::filesystem::path reference;    // empty: no image checks; with `frames`, a %d pattern
  int width = 0, height = 0;          // 0: the reference's size, else the input's
  std::optional<float> time;          // default: the input's [render] time
  std::optional<int> frame;           // uFrame / iFrame of a still; empty: round(time x fps), as render's
  // A frame range A..B: frame f renders at time f / fps with uFrame f, and
  // is compared with the reference pattern's file for f.
  std::optional<std::pair<int, int>> frames;
  double fps = 24.0;
  int spp = 0;                        // 0: the input's
  Backend backend = Backend::automatic;
  std::string renderer;               // GL_RENDERER must contain this ("" = any)
  std::string preset;                 // "" = the input's
  std::vector<std::string> disable;   // shadows, reflections, ao, checker-filter, bloom
  std::vector<std::pair<std::string, std::string>> defines;
  std::vector<std::filesystem::path> allow_include;
  bool specialize = true;
  bool deterministic = false;         // render twice from scratch: bit-identical float pixels
  std::vector<ImageCheck> checks;
  std::optional<CostBudget> cost;
  std::optional<TimeBudget> time_budget;
  int line = 0;                       // its [[case]] line in the suite file

  bool animated() const { return frames.has_value(); }
};

enum class SuiteClock { automatic, cpu, wall };  // automatic: cpu on a software GL, else wall

struct Suite {
  std::filesystem::path file;
  std::string name;         // [suite] name, default the file's stem
  std::string calibration;  // the case whose frame time is 1.0 for every [case.time]
  SuiteClock clock = SuiteClock::automatic;
  std::vector<SuiteCase> cases;  // in file order, globs and backend lists expanded

  const SuiteCase* find(std::string_view name) const;
};

// Throws bad_input naming the file, line and key.
Suite parse_suite(std::string_view toml_text, const std::filesystem::path& display_path);
Suite load_suite(const std::filesystem::path& path);

// Case names matching any of `patterns` (shell globs, fnmatch), or all
// when `patterns` is empty. Throws bad_input (key --only) for a pattern
// that matches nothing.
std::vector<const SuiteCase*> select_cases(const Suite& suite, const std::vector<std::string>& patterns);

}  // namespace ms
