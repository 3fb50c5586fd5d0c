#include "cli/test_cmd.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

#include "suite/outcome.h"
#include "suite/suite.h"
#include "suite/suite_html.h"
#include "suite/suite_report.h"
#include "suite/suite_run.h"
#include "cli/common_flags.h"
#include "cli/dispatch_flag.h"
#include "cli/exit_codes.h"
#include "cli/input_flags.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/utf8.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "pipeline/prepare.h"
#include "pipeline/progress.h"
#include "pipeline/shader_dir.h"
#include "render/aov.h"
#include "render/tiles.h"
#include "shader/assemble.h"

namespace ms {
namespace fs = std::filesystem;

CLI::App* add_test_command(CLI::App& app, TestArgs& a) {
  CLI::App* cmd = app.add_subcommand(
      "test", "Run a suite of image, cost and frame-time tests (docs/testing.md); exit 0 when all pass");
  cmd->add_option("suite", a.suite, "Suite file (.toml)")->required();
  cmd->add_option("--junit", a.junit, "Write JUnit XML here (GitLab, GitHub, Jenkins)");
  cmd->add_option("--report", a.report, "Write an HTML report with every case's images into this directory");
  cmd->add_flag("--json", a.json, "Print the results as JSON on stdout (the case lines go to stderr)");
  cmd->add_flag("--update", a.update, "Write missing and failing references (refused when CI is set)");
  cmd->add_flag("--force", a.force, "Let --update run although CI is set");
  add_enum_flag(cmd, "--exit-codes", a.exit_codes, parse_exit_codes, "{default, idiff}",
                "default (0 pass, 1 fail, 2 bad input, 3 system) or idiff (0 pass, 1 warn, 2 fail, 4 could not run)");
  cmd->add_option("--only", a.only, "Run only the cases whose name matches this glob (repeatable)");
  cmd->add_flag("--list", a.list, "Print the suite's cases, as expanded, and exit");
  cmd->add_flag("-v,--verbose", a.verbose, "Print every compile error of a case that could not run, after its line");
  add_shader_dir_flag(cmd, a.shader_dir);
  // auto is read, then refused by run() with its reason: a suite checks one dispatch.
  add_dispatch_flag(cmd, a.dispatch,
                    "Draw every case's images and counting pass as a fragment pass (default) or a compute dispatch "
                    "(docs/gpu.md)",
                    "{fragment, compute}");
  return cmd;
}

namespace {

// Set to anything but 0 or false, the empty string included (docs/testing.md):
// `CI=` in a pipeline's environment is still a pipeline.
bool ci_is_set() {
  const char* ci = std::getenv("CI");
  return ci && std::strcmp(ci, "0") != 0 && std::strcmp(ci, "false") != 0;
}

// Width and height of the case's reference (its first frame's), when it exists.
bool reference_size(const SuiteCase& c, int& w, int& h) {
  if (c.reference.empty()) return false;
  const fs::path p = c.frames ? FramePattern(c.reference.string()).path(c.frames->first) : c.reference;
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return false;
  const Image img = read_image(p);
  w = img.width;
  h = img.height;
  return true;
}

// Loads and assembles a case exactly as `render -o <reference>` would:
// the frame pipeline's prepare() (pipeline/prepare.h), as a still job.
PreparedCase prepare_case(const Suite& suite, const SuiteCase& c, const fs::path& shader_dir) {
  PreparedCase pc;
  pc.spec = &c;
  try {
    FrameJob job;
    job.input = c.input;
    job.shader_dir = shader_dir;
    job.defines = c.defines;
    job.allow_include = c.allow_include;
    job.specialize = c.specialize ? Specialization::folded : Specialization::generic;
    job.disable = parse_disabled(c.disable);  // checked names (suite/suite_load.cpp)
    job.preset = c.preset;
    job.spp = c.spp;
    pc.format = c.reference.empty() ? ImageFormat::png : image_format_for(c.reference);
    PreparedFrame p = prepare(job, is_display_format(pc.format));
    LoadedInput& in = p.in;
    if (c.cost && in.shadertoy)
      fail_input("case '" + c.name + "': [case.cost] needs an SDF scene, and a Shadertoy shader has no step counters",
                 suite.file.string(), c.line, "cost");
    FrameParams& fp = pc.params;
    fp = p.fp;
    fp.width = c.width;
    fp.height = c.height;
    if (fp.width == 0 && !reference_size(c, fp.width, fp.height)) {
      fp.width = in.scene.render.width;
      fp.height = in.scene.render.height;
    }
    fp.exposure = in.scene.render.exposure;
    pc.fps = still_fps(job, in);  // as render's still
    if (c.cost) {
      AssembleOptions count_opts = job.assemble_options();
      count_opts.graph = p.opts.graph;  // the shape prepare() made
      for (const auto& d : aov_defines()) count_opts.defines.push_back(d);
      pc.counting = assemble_scene(in.scene, count_opts);
      if (c.cost->mean_primitive_evals) {
        if (!in.scene.graph)
          fail_input("case '" + c.name + "': mean_primitive_evals needs a scene graph, and its scene has none",
                     suite.file.string(), c.line, "cost.mean_primitive_evals");
        count_opts.defines.push_back({"MS_COST_PRIMS", "1"});
        pc.counting_prims = assemble_scene(in.scene, count_opts);
      }
    }
    pc.time = c.time ? *c.time : in.scene.render.time;
    check_frame_memory(frame_memory(fp.width, fp.height, frame_targets(c.cost.has_value()), c.cost.has_value()),
                       fp.width, fp.height);
    pc.frame = std::move(p);
  } catch (const Error& e) {
    pc.error = e.info();
  }
  return pc;
}

// The terminal: a line per case; on a TTY also a status line redrawn in place.
class Terminal {
 public:
  explicit Terminal(bool json) : out_(json ? stderr : stdout), tty_(::isatty(2) != 0) {}
  void start(const SuiteCase& c, int index, int total) {
    if (!tty_) return;
    const double eta = index > 0 ? elapsed_.seconds() / index * (total - index) : -1;
    std::fprintf(stderr, "\r[%d/%d] %s ... ETA %s\x1b[K", index + 1, total, c.name.c_str(),
                 format_duration(eta).c_str());
    std::fflush(stderr);
  }
  void done(const CaseResult& r, int index, int total) {
    if (tty_) std::fprintf(stderr, "\r\x1b[K");
    std::fprintf(out_, "[%*d/%d] %s\n", static_cast<int>(std::to_string(total).size()), index, total,
                 valid_utf8(case_line(r)).c_str());
    std::fflush(out_);
  }
  void line(const std::string& text) { std::fprintf(out_, "%s\n", valid_utf8(text).c_str()); }
  // An error's whole log (-v), indented under its case line.
  void detail(const std::string& text) {
    for (size_t at = 0, end; at < text.size(); at = end + 1) {
      end = std::min(text.find('\n', at), text.size());
      if (end > at) std::fprintf(out_, "  %s\n", valid_utf8(text.substr(at, end - at)).c_str());
    }
  }

 private:
  std::FILE* out_;
  bool tty_;
  Stopwatch elapsed_;
};

int run(const TestArgs& a, ExitCodes codes) {
  if (a.force && !a.update) fail_input("--force only goes with --update", {}, 0, "--force");
  if (a.update && ci_is_set() && !a.force)
    fail_input("refusing to write references with CI set: a regression would become the new reference", {}, 0,
               "--update", "update references by hand, look at them and commit them; --force overrides");
  const Dispatch dispatch = a.dispatch;
  if (dispatch == Dispatch::automatic)
    fail_input("test --dispatch auto: a suite checks one dispatch at a time", {}, 0, "--dispatch",
               "give fragment or compute");
  const Suite suite = load_suite(a.suite);
  const std::vector<const SuiteCase*> selected = select_cases(suite, a.only);
  if (a.list) {
    for (const SuiteCase* c : selected)
      std::printf("%s\t%s\t%s\t%s\n", c->name.c_str(), c->input.string().c_str(), backend_name(c->backend),
                  c->reference.empty() ? "-" : c->reference.string().c_str());
    return 0;
  }
  // Output paths before any work, as render checks -o.
  if (!a.junit.empty() && output_kind(a.junit, "--junit") == OutputKind::replace) {
    const fs::path dir = fs::path(a.junit).parent_path().empty() ? "." : fs::path(a.junit).parent_path();
    check_output_directory(dir, "--junit");
  }
  if (!a.report.empty()) {
    std::error_code ec;
    fs::create_directories(a.report, ec);
    if (!fs::is_directory(a.report, ec) || ::access(a.report.c_str(), W_OK) != 0)
      fail_input("cannot make a writable report directory", a.report, 0, "--report");
  }
  const fs::path shader_dir = resolve_shader_dir(a.shader_dir);
  std::vector<PreparedCase> cases;
  for (const SuiteCase* c : selected) cases.push_back(prepare_case(suite, *c, shader_dir));
  std::optional<PreparedCase> calibration;
  const bool timed = std::any_of(selected.begin(), selected.end(), [](const SuiteCase* c) { return c->time_budget; });
  if (timed) {
    calibration = prepare_case(suite, *suite.find(suite.calibration), shader_dir);
    if (calibration->error) {
      ErrorInfo e = *calibration->error;
      e.what = "the calibration case '" + suite.calibration + "': " + e.what;
      throw Error(e);
    }
  }

  Terminal term(a.json);
  RunOptions opts;
  opts.update = a.update;
  opts.dispatch = dispatch;
  opts.report_dir = a.report;
  opts.on_start = [&](const SuiteCase& c, int i, int n) { term.start(c, i, n); };
  opts.on_done = [&](const CaseResult& r, int i, int n) {
    term.done(r, i, n);
    if (a.verbose) term.detail(r.detail);
  };
  const SuiteResult result = run_suite(suite, cases, calibration ? &*calibration : nullptr, opts);

  std::vector<std::string> updated;
  for (const CaseResult& c : result.cases)
    for (const Updated& u : c.updated) updated.push_back("  " + u.path.string() + " (" + u.why + ")");
  if (a.update) {
    term.line(updated.empty() ? "no reference needed updating"
                              : "updated " + std::to_string(updated.size()) + " reference" +
                                    (updated.size() > 1 ? "s" : "") + " (look at them before committing):");
    for (const std::string& u : updated) term.line(u);
  }
  if (!a.junit.empty()) write_text_file(a.junit, suite_junit(suite, result), "--junit");
  if (!a.report.empty()) write_html_report(a.report, suite, result);
  if (a.json) std::fputs(suite_json(suite, result).c_str(), stdout);
  term.line(summary_line(result));
  if (!a.report.empty()) term.line("report: " + (fs::path(a.report) / "index.html").string());
  if (!a.junit.empty()) term.line("junit: " + a.junit);
  std::fflush(stdout);
  return exit_code_for(codes, result.worst(), result.worst_error());
}

}  // namespace

int run_test(const TestArgs& a) {
  return run_with_exit_codes(a.exit_codes, [&] { return run(a, a.exit_codes); });
}

}  // namespace ms
