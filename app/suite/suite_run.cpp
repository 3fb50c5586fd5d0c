#include "suite/suite_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "core/clock.h"
#include "bench/stats.h"
#include "core/format.h"
#include "suite/suite_gl.h"
#include "suite/suite_report.h"
#include "gl/context.h"
#include "render/bloom.h"
#include "render/program_cache.h"
#include "render/still.h"
#include "scene/animation.h"
#include "shader/assemble.h"

namespace ms {
namespace fs = std::filesystem;

using suite_detail::FrameSpec;
using suite_detail::Gl;
using suite_detail::check_images;
using suite_detail::frames_of;
using suite_detail::still_of;

namespace suite_detail {

std::vector<FrameSpec> frames_of(const PreparedCase& pc) {
  const SuiteCase& c = *pc.spec;
  if (!c.frames) return {{c.frame.value_or(still_frame_number(pc.time, pc.fps)), pc.time, 1.0f / 60.0f}};
  std::vector<FrameSpec> out;
  // As `render --frames`: frame f at f / fps, exactly as the shader gets it.
  for (int f = c.frames->first; f <= c.frames->second; ++f)
    out.push_back({f, static_cast<float>(static_cast<double>(f) / c.fps), static_cast<float>(1.0 / c.fps)});
  return out;
}

FramePrograms& Gl::job(const PreparedCase& pc, Dispatch d) {
  std::unique_ptr<FramePrograms>& j = jobs[{&pc, d}];
  if (!j) {
    j = std::make_unique<FramePrograms>(ctx, session.cache(), pc.frame);
    if (d == Dispatch::compute) j->choose(d, std::nullopt, StillFrame{}, false);
  }
  return *j;
}

StillFrame still_of(const PreparedCase& pc, const Scene& posed, const FrameSpec& f) {
  StillFrame s;
  s.in.scene = &posed;
  s.in.time = f.time;
  s.in.time_delta = f.time_delta;
  s.in.frame = f.frame;
  std::copy(std::begin(posed.shadertoy.mouse), std::end(posed.shadertoy.mouse), s.in.mouse);
  s.fps = pc.spec->frames ? pc.spec->fps : pc.fps;  // a range's own fps, as `render --frames`
  s.params = pc.params;
  s.params.exposure = posed.render.exposure;  // keyframed exposure, as render poses it
  return s;
}

}  // namespace suite_detail

namespace {


// Median frame time of `frames` draws after `warmup`, on `cpu` or wall time.
double time_frames(FramePrograms& job, const StillFrame& sf, int warmup, int frames, bool cpu, std::vector<double>& all) {
  for (int i = 0; i < warmup; ++i) job.submit(sf.in, sf.params);
  glFinish();
  std::vector<double> t;
  for (int i = 0; i < frames; ++i) {
    const Clock::time_point w0 = Clock::now();
    const double u0 = process_cpu_ms();
    job.submit(sf.in, sf.params);  // one frame, as a sequence draws it
    glFinish();
    t.push_back(cpu ? process_cpu_ms() - u0 : ms_since(w0));
  }
  all.insert(all.end(), t.begin(), t.end());
  return summarize(t).median;
}

void budget(CaseResult& r, const std::string& name, double value, double bound, Outcome o, std::string note) {
  r.budgets.push_back({name, value, bound, o, std::move(note)});
}

void check_cost(const CostBudget& b, const BenchCost& cost, CaseResult& r) {
  const struct {
    const char* name;
    const std::optional<double>& bound;
    double value;
    bool slack;  // subject to max_slack
  } rows[] = {{"mean_primary_steps", b.mean_primary_steps, cost.primary_steps.mean, true},
              {"p99_primary_steps", b.p99_primary_steps, cost.primary_steps.p99, true},
              {"mean_map_calls", b.mean_map_calls, cost.sdf_evals.mean, true},
              {"p99_map_calls", b.p99_map_calls, cost.sdf_evals.p99, true},
              {"step_cap_fraction", b.step_cap_fraction, cost.step_cap_fraction, false},
              {"mean_primitive_evals", b.mean_primitive_evals,
               cost.primitive_evals ? cost.primitive_evals->mean : 0.0, true}};
  for (const auto& row : rows) {
    if (!row.bound) continue;
    const double bound = *row.bound;
    if (row.value > bound) {
      budget(r, row.name, row.value, bound, Outcome::fail,
             std::string(row.name) + " " + format_value(row.value) + " > " + format_value(bound) + ": costs more");
    } else if (row.slack && b.max_slack && row.value < bound / *b.max_slack) {
      budget(r, row.name, row.value, bound, Outcome::fail,
             std::string(row.name) + " " + format_value(row.value) + " is under " + format_value(bound) + " / " +
                 format_value(*b.max_slack) + ": cheaper now, lower the bound");
    } else {
      budget(r, row.name, row.value, bound, Outcome::pass,
             std::string(row.name) + " " + format_value(row.value) + " <= " + format_value(bound));
    }
  }
}

// The frame-time ratio to the calibration case: rounds of calibration
// frames then case frames, back to back, so load from elsewhere slows both.
void check_time(Gl& gl, const Suite& suite, const PreparedCase& pc, const PreparedCase& cal, CaseResult& r) {
  const TimeBudget& b = *pc.spec->time_budget;
  const bool cpu = suite.clock == SuiteClock::cpu || (suite.clock == SuiteClock::automatic && gl.ctx.info().software());
  FramePrograms& cal_job = gl.job(cal);
  FramePrograms& job = gl.job(pc);
  const Scene cal_posed = animated(cal.frame.in.scene, frames_of(cal).front().time);
  const Scene posed = animated(pc.frame.in.scene, frames_of(pc).front().time);
  const StillFrame cal_sf = still_of(cal, cal_posed, frames_of(cal).front());
  const StillFrame sf = still_of(pc, posed, frames_of(pc).front());
  std::vector<double> ratios, cal_all, case_all;
  for (int i = 0; i < b.rounds; ++i) {
    const double c = time_frames(cal_job, cal_sf, b.warmup, b.frames, cpu, cal_all);
    const double t = time_frames(job, sf, b.warmup, b.frames, cpu, case_all);
    ratios.push_back(c > 0 ? t / c : 0.0);
  }
  FrameTime ft{summarize(case_all).median, summarize(cal_all).median, summarize(ratios).median, cpu ? "cpu" : "wall"};
  r.frame_time = ft;
  auto two = [](double v) { return printf_number("%.2f", v); };
  const std::string what = "frame time " + two(ft.ratio) + "x " + suite.calibration + "'s (" + two(ft.case_ms) +
                           " ms vs " + two(ft.calibration_ms) + " ms of " + ft.clock + " time)";
  if (ft.ratio > b.max_ratio)
    budget(r, "frame_time_ratio", ft.ratio, b.max_ratio, Outcome::fail, what + " > " + format_value(b.max_ratio));
  else if (b.warn_ratio && ft.ratio > *b.warn_ratio)
    budget(r, "frame_time_ratio", ft.ratio, b.max_ratio, Outcome::warn, what + " > warn " + format_value(*b.warn_ratio));
  else
    budget(r, "frame_time_ratio", ft.ratio, b.max_ratio, Outcome::pass, what + " <= " + format_value(b.max_ratio));
}

CaseResult run_case(Gl& gl, const Suite& suite, const PreparedCase& pc, const PreparedCase* cal,
                    const RunOptions& opts) {
  const SuiteCase& c = *pc.spec;
  CaseResult r;
  r.spec = &c;
  r.backend = gl.ctx.backend();
  r.renderer = gl.ctx.info().renderer;
  r.width = pc.params.width;
  r.height = pc.params.height;
  r.frames = c.frames ? c.frames->second - c.frames->first + 1 : 1;
  if (!c.renderer.empty() && r.renderer.find(c.renderer) == std::string::npos)
    fail_system("needs a GL_RENDERER with '" + c.renderer + "', this context is " + r.renderer + " (" + r.backend + ")");
  check_frame_size(gl.ctx.info(), r.width, r.height, frame_targets(c.cost.has_value()));
  if (!c.checks.empty() || c.deterministic) check_images(gl, pc, opts, r);
  if (c.cost) {
    FramePrograms& job = gl.job(pc, opts.dispatch);
    const FrameSpec f = frames_of(pc).front();
    const Scene posed = animated(pc.frame.in.scene, f.time);
    r.cost = count_frame_cost(job, pc.counting, posed, f.time, pc.params);
    if (c.cost->mean_primitive_evals)
      r.cost->primitive_evals = count_frame_cost(job, pc.counting_prims, posed, f.time, pc.params).sdf_evals;
    check_cost(*c.cost, *r.cost, r);
  }
  if (c.time_budget && cal) check_time(gl, suite, pc, *cal, r);
  return r;
}

// The case's outcome and its one-line message from everything checked.
void conclude(CaseResult& r) {
  std::vector<std::string> fails, warns;
  for (const CheckResult& cr : r.checks) {
    r.outcome = std::max(r.outcome, cr.outcome);
    if (cr.outcome == Outcome::fail) fails.push_back(check_text(cr));
    if (cr.outcome == Outcome::warn) warns.push_back(check_text(cr));
  }
  for (const BudgetResult& b : r.budgets) {
    r.outcome = std::max(r.outcome, b.outcome);
    if (b.outcome == Outcome::fail) fails.push_back(b.note);
    if (b.outcome == Outcome::warn) warns.push_back(b.note);
  }
  if (r.nondeterministic_values && *r.nondeterministic_values > 0) {
    r.outcome = std::max(r.outcome, Outcome::fail);
    fails.push_back(std::to_string(*r.nondeterministic_values) + " values differ between two identical renders");
  }
  if (!r.message.empty()) return;  // a reference problem says it first
  if (fails.empty() && !r.updated.empty()) {
    r.message = "updated " + std::to_string(r.updated.size()) + " reference" + (r.updated.size() > 1 ? "s" : "") +
                " (" + r.updated.front().why + ")";
    for (const std::string& w : warns) r.message += "; " + w;
    return;
  }
  r.message_sums_up = true;
  const std::vector<std::string>& lines = !fails.empty() ? fails : warns;
  for (const std::string& l : lines) r.message += (r.message.empty() ? "" : "; ") + l;
  if (r.message.empty()) {  // everything passed: say what
    std::vector<std::string> parts;
    for (const CheckResult& cr : r.checks) parts.push_back(check_text(cr));
    for (const BudgetResult& b : r.budgets) parts.push_back(b.note);
    if (r.nondeterministic_values) parts.push_back("bit-identical twice");
    for (const std::string& p : parts) r.message += (r.message.empty() ? "" : "; ") + p;
  }
}

CaseResult error_result(const SuiteCase& c, const ErrorInfo& e) {
  CaseResult r;
  r.spec = &c;
  r.outcome = Outcome::error;
  r.error_code = e.code == Exit::system ? Exit::system : Exit::bad_input;
  r.message = format_error(e);
  r.detail = e.detail;
  return r;
}

}  // namespace

Outcome SuiteResult::worst() const {
  Outcome o = Outcome::pass;
  for (const CaseResult& c : cases) o = std::max(o, c.outcome);
  return o;
}

Exit SuiteResult::worst_error() const {
  for (const CaseResult& c : cases)
    if (c.outcome == Outcome::error && c.error_code == Exit::system) return Exit::system;
  return Exit::bad_input;
}

SuiteResult run_suite(const Suite& suite, const std::vector<PreparedCase>& cases, const PreparedCase* calibration,
                      const RunOptions& opts) {
  const Clock::time_point t0 = Clock::now();
  SuiteResult out;
  out.cases.resize(cases.size());
  // Backends in order of first use; each gets one context for all its cases.
  std::vector<Backend> backends;
  for (const PreparedCase& pc : cases)
    if (std::find(backends.begin(), backends.end(), pc.spec->backend) == backends.end())
      backends.push_back(pc.spec->backend);
  const int total = static_cast<int>(cases.size());
  int done = 0;
  for (const Backend be : backends) {
    FrameSession session;
    std::optional<ErrorInfo> no_context;
    try {
      const Context& ctx = session.context(be);
      out.machines.emplace_back(ctx.backend(), ctx.info().renderer);
    } catch (const Error& e) {
      no_context = e.info();
    }
    std::optional<Gl> gl;
    if (session.has_context()) gl.emplace(session);
    for (size_t i = 0; i < cases.size(); ++i) {
      const PreparedCase& pc = cases[i];
      if (pc.spec->backend != be) continue;
      if (opts.on_start) opts.on_start(*pc.spec, done, total);
      const Clock::time_point c0 = Clock::now();
      CaseResult r;
      if (pc.error) {
        r = error_result(*pc.spec, *pc.error);
      } else if (no_context) {
        r = error_result(*pc.spec, *no_context);
      } else {
        try {
          r = run_case(*gl, suite, pc, calibration, opts);
          conclude(r);
        } catch (const Error& e) {
          r = error_result(*pc.spec, e.info());
        } catch (const std::bad_alloc&) {
          r = error_result(*pc.spec, {Exit::system, {}, 0, {}, "out of memory", {}, {}});
        }
      }
      r.seconds = seconds_since(c0);
      out.cases[i] = std::move(r);
      if (opts.on_done) opts.on_done(out.cases[i], ++done, total);
    }
  }
  out.seconds = seconds_since(t0);
  return out;
}

}  // namespace ms
