// The image checks of `marchstudio test` (suite/suite_gl.h): each frame
// against its reference, the --update writes, determinism and the report's images.
#include <cstring>
#include <optional>

#include "suite/suite_gl.h"
#include "suite/suite_html.h"
#include "suite/suite_report.h"
#include "core/version.h"
#include "io/flip.h"
#include "io/sequence.h"
#include "io/stored_pixels.h"
#include "render/scene_drawer.h"
#include "scene/animation.h"

namespace ms::suite_detail {
namespace fs = std::filesystem;

namespace {

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

long long differing_values(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size()) return static_cast<long long>(std::max(a.pixels.size(), b.pixels.size()));
  long long n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
  return n;
}

}  // namespace

void check_images(Gl& gl, const PreparedCase& pc, const RunOptions& opts, CaseResult& r) {
  const SuiteCase& c = *pc.spec;
  FramePrograms& job = gl.job(pc, opts.dispatch);  // test --dispatch compute: its scene pass (render/scene_drawer.h)
  for (const ImageCheck& ch : c.checks) r.checks.push_back({ch, 0.0, -1, Outcome::pass, {}});
  std::vector<std::string> problems;  // missing or mismatched references, one line each
  Image shown_ref, shown_got;
  bool shown = false;
  std::vector<bool> seen(r.checks.size(), false);  // a check has a value from some frame
  const std::vector<FrameSpec> frames = frames_of(pc);
  for (const FrameSpec& f : frames) {
    const Scene posed = animated(pc.frame.in.scene, f.time);
    const StillFrame sf = still_of(pc, posed, f);
    // A stateful shader's frames follow on: the first is a still (frames
    // 0..first replayed), the rest each one frame more, as a sequence.
    const bool from_start = &f == &frames.front() || !job.graph().stateful();
    if (from_start) job.submit_still(sf);
    else job.submit(sf.in, sf.params);
    const Still still = job.read(sf.params.aovs);
    if (c.deterministic && &f == &frames.front()) {
      // From scratch: a fresh compile and fresh targets, as another run would.
      ProgramCache fresh(8);
      FramePrograms again(gl.ctx, fresh, pc.frame);
      if (opts.dispatch == Dispatch::compute) again.choose(opts.dispatch, std::nullopt, sf, false);
      r.nondeterministic_values = differing_values(still.color, again.draw(sf).color);
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
      write_image(still.color, ref_path, {{"Software", std::string(kSoftware) + " test --update"}});
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

}  // namespace ms::suite_detail
