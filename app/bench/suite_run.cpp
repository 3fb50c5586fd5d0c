#include "bench/suite_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <optional>

#include "bench/clock.h"
#include "bench/flip.h"
#include "bench/stats.h"
#include "bench/suite_html.h"
#include "bench/suite_report.h"
#include "gl/context.h"
#include "io/sequence.h"
#include "io/stored_pixels.h"
#include "render/bloom.h"
#include "render/program_cache.h"
#include "render/still.h"
#include "scene/animation.h"
#include "shader/assemble.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// One backend's context and everything that shares it.
struct Gl {
  explicit Gl(const Context& c) : ctx(c), cache(64), renderer(c) {}
  const Context& ctx;
  ProgramCache cache;
  FrameRenderer renderer;
  std::map<const PreparedCase*, std::unique_ptr<PassGraph>> graphs;  // programs shared through `cache`
  const std::string vs = fullscreen_vertex_source();
  std::shared_ptr<const Program> program(const ShaderSource& src) { return cache.get(vs, src); }
  PassGraph& graph(const PreparedCase& pc) {
    std::unique_ptr<PassGraph>& g = graphs[&pc];
    if (!g) g = std::make_unique<PassGraph>(pc.passes, &cache);
    return *g;
  }
  std::map<const PreparedCase*, std::unique_ptr<BloomStage>> blooms;
  // The case's bloom stage, as render builds it; nullptr without bloom.
  BloomStage* bloom(const PreparedCase& pc) {
    if (pc.bloom.size() != 2) return nullptr;
    std::unique_ptr<BloomStage>& b = blooms[&pc];
    if (!b) b = std::make_unique<BloomStage>(pc.scene.bloom, program(pc.bloom[0]), program(pc.bloom[1]));
    return b.get();
  }
};

struct FrameSpec {
  int frame = 0;
  float time = 0.0f, time_delta = 1.0f / 60.0f;
};

std::vector<FrameSpec> frames_of(const PreparedCase& pc) {
  const SuiteCase& c = *pc.spec;
  if (!c.frames) return {{c.frame, pc.time, 1.0f / 60.0f}};
  std::vector<FrameSpec> out;
  // As `render --frames`: frame f at f / fps, exactly as the shader gets it.
  for (int f = c.frames->first; f <= c.frames->second; ++f)
    out.push_back({f, static_cast<float>(static_cast<double>(f) / c.fps), static_cast<float>(1.0 / c.fps)});
  return out;
}

StillFrame still_of(Gl& gl, const PreparedCase& pc, const Scene& posed, const FrameSpec& f) {
  StillFrame s;
  s.in.scene = &posed;
  s.in.time = f.time;
  s.in.time_delta = f.time_delta;
  s.in.frame = f.frame;
  std::copy(std::begin(posed.shadertoy.mouse), std::end(posed.shadertoy.mouse), s.in.mouse);
  s.fps = pc.spec->frames ? pc.spec->fps : pc.fps;  // a range's own fps, as `render --frames`
  s.params = pc.params;
  s.params.exposure = posed.render.exposure;  // keyframed exposure, as render poses it
  s.params.bloom = gl.bloom(pc);
  return s;
}

fs::path reference_of(const SuiteCase& c, int frame) {
  return c.frames ? FramePattern(c.reference.string()).path(frame) : c.reference;
}

bool worse(const CheckResult& r, double v, Outcome o) {
  if (o != r.outcome) return o > r.outcome;
  return r.check.metric == Metric::psnr ? v < r.value : v > r.value;
}

// Compares one frame for one check and returns its outcome; keeps the
// figures when this is the first frame or the worst so far (`kept`).
Outcome measure(CheckResult& cr, const Image& ref, const Image& got, int frame, bool first, bool& kept) {
  CompareOptions co;
  co.pixel_threshold = cr.check.pixel_threshold;
  if (cr.check.metric == Metric::flip) co.flip_ppd = flip_default_ppd();
  const CompareMetrics m = compare_images(ref, got, co);
  const double v = metric_value(m, cr.check.metric);
  const Outcome o = classify(m, cr.check.metric, cr.check.threshold, cr.check.warn);
  kept = first || worse(cr, v, o);
  if (kept) {
    cr.value = v;
    cr.outcome = o;
    cr.metrics = m;
    cr.frame = frame;
  }
  return o;
}

// Median frame time of `frames` draws after `warmup`, on `cpu` or wall time.
double time_frames(Gl& gl, PassGraph& graph, const Program& post, const StillFrame& sf, int warmup, int frames,
                   bool cpu, std::vector<double>& all) {
  for (int i = 0; i < warmup; ++i) graph.draw(gl.renderer, post, sf.in, sf.params);
  glFinish();
  std::vector<double> t;
  for (int i = 0; i < frames; ++i) {
    const Clock::time_point w0 = Clock::now();
    const double u0 = process_cpu_ms();
    graph.draw(gl.renderer, post, sf.in, sf.params);  // one frame, as a sequence draws it
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
              {"step_cap_fraction", b.step_cap_fraction, cost.step_cap_fraction, false}};
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
  PassGraph& cal_graph = gl.graph(cal);
  PassGraph& graph = gl.graph(pc);
  const auto cal_post = gl.program(cal.post), post = gl.program(pc.post);
  const Scene cal_posed = animated(cal.scene, frames_of(cal).front().time);
  const Scene posed = animated(pc.scene, frames_of(pc).front().time);
  const StillFrame cal_sf = still_of(gl, cal, cal_posed, frames_of(cal).front());
  const StillFrame sf = still_of(gl, pc, posed, frames_of(pc).front());
  std::vector<double> ratios, cal_all, case_all;
  for (int i = 0; i < b.rounds; ++i) {
    const double c = time_frames(gl, cal_graph, *cal_post, cal_sf, b.warmup, b.frames, cpu, cal_all);
    const double t = time_frames(gl, graph, *post, sf, b.warmup, b.frames, cpu, case_all);
    ratios.push_back(c > 0 ? t / c : 0.0);
  }
  FrameTime ft{summarize(case_all).median, summarize(cal_all).median, summarize(ratios).median, cpu ? "cpu" : "wall"};
  r.frame_time = ft;
  auto two = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return std::string(buf);
  };
  const std::string what = "frame time " + two(ft.ratio) + "x " + suite.calibration + "'s (" + two(ft.case_ms) +
                           " ms vs " + two(ft.calibration_ms) + " ms of " + ft.clock + " time)";
  if (ft.ratio > b.max_ratio)
    budget(r, "frame_time_ratio", ft.ratio, b.max_ratio, Outcome::fail, what + " > " + format_value(b.max_ratio));
  else if (b.warn_ratio && ft.ratio > *b.warn_ratio)
    budget(r, "frame_time_ratio", ft.ratio, b.max_ratio, Outcome::warn, what + " > warn " + format_value(*b.warn_ratio));
  else
    budget(r, "frame_time_ratio", ft.ratio, b.max_ratio, Outcome::pass, what + " <= " + format_value(b.max_ratio));
}

long long differing_values(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size()) return static_cast<long long>(std::max(a.pixels.size(), b.pixels.size()));
  long long n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
  return n;
}

// The image checks of every frame, the --update writes and the report's
// images (of the worst frame).
void check_images(Gl& gl, const PreparedCase& pc, const RunOptions& opts, CaseResult& r) {
  const SuiteCase& c = *pc.spec;
  PassGraph& graph = gl.graph(pc);
  const auto post = gl.program(pc.post);
  for (const ImageCheck& ch : c.checks) r.checks.push_back({ch, 0.0, -1, Outcome::pass, {}});
  std::vector<std::string> problems;  // missing or mismatched references, one line each
  Image shown_ref, shown_got;
  bool shown = false;
  std::vector<bool> seen(r.checks.size(), false);  // a check has a value from some frame
  const std::vector<FrameSpec> frames = frames_of(pc);
  std::optional<SceneDrawer> compute;  // test --dispatch compute (render/scene_drawer.h)
  if (opts.dispatch == Dispatch::compute) compute.emplace(gl.ctx, graph, Dispatch::compute);
  for (const FrameSpec& f : frames) {
    const Scene posed = animated(pc.scene, f.time);
    const StillFrame sf = still_of(gl, pc, posed, f);
    // A stateful shader's frames follow on: the first is a still (frames
    // 0..first replayed), the rest each one frame more, as a sequence.
    const bool from_start = &f == &frames.front() || !graph.stateful();
    if (compute) from_start ? compute->draw_still(graph, *post, sf) : compute->draw(graph, *post, sf.in, sf.params);
    const Still still = compute      ? compute->read(sf.params.aovs)
                        : from_start ? render_still(gl.renderer, graph, *post, sf)
                                     : render_frame(gl.renderer, graph, *post, sf.in, sf.params);
    if (c.deterministic && &f == &frames.front()) {
      // From scratch: a fresh compile and fresh targets, as another run would.
      PassGraph graph2(pc.passes);
      const Program post2(gl.vs, pc.post);
      SceneDrawer again(gl.ctx, graph2, opts.dispatch);
      again.draw_still(graph2, post2, sf);
      r.nondeterministic_values = differing_values(still.color, again.read(false).color);
    }
    if (c.checks.empty()) continue;
    const Image got = stored_pixels(still.color, pc.format);
    const fs::path ref_path = reference_of(c, f.frame);
    const std::string at = c.frames ? " (frame " + std::to_string(f.frame) + ")" : "";
    std::string bad;  // why this frame's reference is no good, if it is not
    Image ref;
    std::error_code ec;
    if (!fs::exists(ref_path, ec)) {
      bad = "no reference " + ref_path.string();
    } else {
      try {
        ref = read_image(ref_path);
      } catch (const Error& e) {
        if (!opts.update) throw;
        bad = "unreadable reference: " + e.info().what;
      }
      if (bad.empty() && (ref.width != got.width || ref.height != got.height || ref.nchannels() != got.nchannels()))
        bad = "reference " + ref_path.string() + " is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) +
              " with " + std::to_string(ref.nchannels()) + " channels, the render " + std::to_string(got.width) + "x" +
              std::to_string(got.height) + " with " + std::to_string(got.nchannels());
    }
    bool frame_failed = !bad.empty();
    if (bad.empty()) {
      for (size_t k = 0; k < r.checks.size(); ++k) {
        bool kept = false;
        frame_failed = measure(r.checks[k], ref, got, c.frames ? f.frame : -1, !seen[k], kept) == Outcome::fail ||
                       frame_failed;
        seen[k] = true;
        if (kept && k == 0) shown = false;  // the report shows the first check's worst frame
      }
    }
    if (frame_failed && opts.update) {
      std::string why = bad.empty() ? "" : (fs::exists(ref_path, ec) ? bad : "new");
      for (const CheckResult& cr : r.checks)
        if (why.empty() && cr.outcome == Outcome::fail && cr.frame == (c.frames ? f.frame : -1)) why = check_text(cr);
      if (why.empty()) why = "failed";
      fs::create_directories(ref_path.parent_path().empty() ? fs::path(".") : ref_path.parent_path(), ec);
      write_image(still.color, ref_path, {{"Software", "marchstudio 0.1.0 test --update"}});
      r.updated.push_back({ref_path, why});
      ref = got;
      bad.clear();
      for (size_t k = 0; k < r.checks.size(); ++k) {  // a new reference is this render
        bool kept = false;
        if (!seen[k]) measure(r.checks[k], ref, got, c.frames ? f.frame : -1, true, kept);
        seen[k] = true;
      }
    } else if (!bad.empty()) {
      problems.push_back(bad + at);
    }
    if (!shown) {
      shown_ref = ref;
      shown_got = got;
      shown = true;
    }
  }
  if (!problems.empty()) {
    // A missing reference is input the suite lacks; a mismatched one fails.
    const bool missing = problems.front().rfind("no reference", 0) == 0;
    for (CheckResult& cr : r.checks) cr.outcome = missing ? Outcome::error : Outcome::fail;
    r.message = problems.front() + (missing ? ": `marchstudio test --update` writes it (then look at it)" : "");
    if (missing) r.error_code = Exit::bad_input;
  }
  if (!r.updated.empty())  // the updated frames compare with themselves now
    for (CheckResult& cr : r.checks)
      if (cr.outcome == Outcome::fail) cr.outcome = Outcome::pass;
  if (!opts.report_dir.empty()) write_case_images(opts.report_dir, r, shown_ref, shown_got);
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
  check_frame_size(gl.ctx.info(), r.width, r.height, c.cost ? 6 : 2);
  if (!c.checks.empty() || c.deterministic) check_images(gl, pc, opts, r);
  if (c.cost) {
    const auto counting = gl.program(pc.counting), post = gl.program(pc.post);
    const FrameSpec f = frames_of(pc).front();
    FrameParams fp = pc.params;
    fp.bloom = gl.bloom(pc);  // its post pass adds bloom
    if (opts.dispatch == Dispatch::compute) {
      SceneDrawer d(gl.ctx, gl.graph(pc), Dispatch::compute);
      r.cost = count_frame_cost(d, *d.program(pc.counting), *post, animated(pc.scene, f.time), f.time, fp);
    } else {
      r.cost = count_frame_cost(gl.renderer, *counting, *post, animated(pc.scene, f.time), f.time, fp);
    }
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
  std::vector<std::string> backends;
  for (const PreparedCase& pc : cases)
    if (std::find(backends.begin(), backends.end(), pc.spec->backend) == backends.end())
      backends.push_back(pc.spec->backend);
  const int total = static_cast<int>(cases.size());
  int done = 0;
  for (const std::string& be : backends) {
    std::unique_ptr<Context> ctx;
    std::optional<ErrorInfo> no_context;
    try {
      ctx = create_headless_context(parse_backend(be));
      out.machines.emplace_back(ctx->backend(), ctx->info().renderer);
    } catch (const Error& e) {
      no_context = e.info();
    }
    std::optional<Gl> gl;
    if (ctx) gl.emplace(*ctx);
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
      r.seconds = std::chrono::duration<double>(Clock::now() - c0).count();
      out.cases[i] = std::move(r);
      if (opts.on_done) opts.on_done(out.cases[i], ++done, total);
    }
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

}  // namespace ms
