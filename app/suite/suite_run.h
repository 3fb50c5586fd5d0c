// Running a suite: every selected case rendered through the frame pipeline
// as `render` (pipeline/frame_session.h), one GL context per backend in one
// process, programs shared through its ProgramCache; then its image checks,
// cost budgets (bench's counting pass), frame-time ratio and determinism.
// The caller loads and assembles each case (cli/test_cmd.cpp, as `render`
// does) before any context exists; this file never parses flags.
#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "suite/outcome.h"
#include "suite/suite.h"
#include "core/error.h"
#include "io/image.h"
#include "io/image_io.h"
#include "pipeline/prepare.h"
#include "render/frame.h"
#include "render/graph.h"
#include "scene/scene.h"
#include "preprocess/preprocess.h"

namespace ms {

// A case ready to render: what `render -o <reference>` would build.
struct PreparedCase {
  const SuiteCase* spec = nullptr;
  PreparedFrame frame;        // pipeline/prepare.h, for the reference's format: its scene posed per frame
  double fps = 60.0;          // a still's frame rate: a shader's own (60), a scene's render --fps default
  ShaderSource counting;      // the AOV build, when spec->cost
  ShaderSource counting_prims;  // and counting primitives, when it bounds mean_primitive_evals
  FrameParams params;         // size, spp, exposure, fused_post
  ImageFormat format = ImageFormat::png;  // the reference's (what the render is stored as)
  float time = 0.0f;          // of a still
  std::optional<ErrorInfo> error;  // could not be prepared (bad input): reported, not run
};

struct CheckResult {
  ImageCheck check;
  double value = 0.0;   // the worst over the frames
  int frame = -1;       // where (a frame-range case), else -1
  Outcome outcome = Outcome::pass;
  CompareMetrics metrics;  // of that frame
};

// One budget: a cost bound or the frame-time ratio.
struct BudgetResult {
  std::string name;     // "mean_primary_steps", ..., "frame_time_ratio"
  double value = 0.0, bound = 0.0;
  Outcome outcome = Outcome::pass;
  std::string note;     // why it failed or warned, one line
};

struct FrameTime {
  double case_ms = 0.0, calibration_ms = 0.0;  // medians over every timed frame
  double ratio = 0.0;                          // median of the rounds' ratios
  std::string clock;                           // "cpu" | "wall"
};

struct Updated {
  std::filesystem::path path;
  std::string why;  // "new", or the failure it replaces
};

struct CaseResult {
  const SuiteCase* spec = nullptr;
  Outcome outcome = Outcome::pass;
  Exit error_code = Exit::ok;  // bad_input or system when outcome is error
  std::string message;         // one line: the first failure, or what passed
  bool message_sums_up = false;  // the message only repeats the checks and budgets below
  std::string detail;            // an error's whole compile log, one diagnostic a line (test -v)
  std::string backend, renderer;
  int width = 0, height = 0, frames = 1;
  double seconds = 0.0;
  std::vector<CheckResult> checks;
  std::optional<BenchCost> cost;
  std::optional<FrameTime> frame_time;
  std::vector<BudgetResult> budgets;
  std::optional<long long> nondeterministic_values;  // with `deterministic`: values that differed
  std::vector<Updated> updated;                       // --update: references written
  // Report images, relative to the report directory ("" when none).
  std::string image_reference, image_result, image_diff;
};

struct RunOptions {
  bool update = false;                 // write missing and failing references
  // What draws each case's images and counting pass (test --dispatch):
  // fragment or compute; frame-time budgets are timed with fragment.
  Dispatch dispatch = Dispatch::fragment;
  std::filesystem::path report_dir;    // write each case's images here ("" = none)
  // Progress: before a case and after it (in run order: grouped by backend).
  std::function<void(const SuiteCase&, int index, int total)> on_start;
  std::function<void(const CaseResult&, int index, int total)> on_done;
};

struct SuiteResult {
  std::vector<CaseResult> cases;  // in suite order
  std::vector<std::pair<std::string, std::string>> machines;  // backend -> GL_RENDERER, per context made
  double seconds = 0.0;
  Outcome worst() const;
  Exit worst_error() const;  // system when any case failed for the system, else bad_input
};

// `calibration`: the suite's calibration case, prepared (nullptr when no
// case has a frame-time budget).
SuiteResult run_suite(const Suite& suite, const std::vector<PreparedCase>& cases, const PreparedCase* calibration,
                      const RunOptions& opts);

}  // namespace ms
