#include "cli/compare_cmd.h"

#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "suite/outcome.h"
#include "cli/common_flags.h"
#include "cli/exit_codes.h"
#include "core/format.h"
#include "core/error.h"
#include "core/version.h"
#include "io/compare.h"
#include "io/flip.h"
#include "io/image_io.h"

namespace ms {

CLI::App* add_compare_command(CLI::App& app, CompareArgs& a) {
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare image B against reference A; exit 0 within the threshold, 1 over it");
  cmd->add_option("a", a.a, "Reference image (e.g. a golden)")->required();
  cmd->add_option("b", a.b, "Image to check")->required();
  add_enum_flag(cmd, "--metric", a.metric, parse_metric, "{psnr, mae, max, fraction, flip}",
                "Metric the threshold applies to: psnr, mae, max, fraction, flip (default psnr)");
  cmd->add_option("--threshold", a.threshold,
                  "psnr: fail when PSNR (dB) < X; mae, max, fraction: fail when value > X "
                  "(default: the images must match exactly)")
      ->each([&a](const std::string&) { a.threshold_set = true; });
  cmd->add_option("--warn", a.warn,
                  "Warn (pass, but report it; idiff exit code 1) when the metric is past X but within --threshold")
      ->each([&a](const std::string&) { a.warn_set = true; });
  add_enum_flag(cmd, "--exit-codes", a.exit_codes, parse_exit_codes, "{default, idiff}",
                "default (0 pass, 1 fail, 2 bad input, 3 system) or idiff (0 pass, 1 warn, 2 fail, 4 could not run)");
  cmd->add_option("--pixel-threshold", a.pixel_threshold,
                  "A pixel is 'different' when a channel differs by more than T (default 1/255)");
  cmd->add_option("--diff", a.diff, "Write a heat map of |A-B| here (.png .jpg .tif .exr)");
  cmd->add_flag("--json", a.json, "Print the metrics as JSON");
  return cmd;
}

namespace {

// Errors from io/ name the output flag as -o; here it is --diff. Messages
// from OpenImageIO can span lines; every error we print is one line.
[[noreturn]] void rethrow_as(const Error& e, const std::string& key) {
  ErrorInfo info = e.info();
  if (!key.empty() && info.key == "-o") info.key = key;
  for (char& c : info.what)
    if (c == '\n' || c == '\r') c = ' ';
  while (!info.what.empty() && info.what.back() == ' ') info.what.pop_back();
  throw Error(info);
}

// libpng prints decode errors to stderr itself before OpenImageIO returns
// the same text to us; hold fd 2 on /dev/null while reading so that a bad
// file gives the one-line error every other failure gives.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
      ::dup2(null, 2);
      ::close(null);
    }
  }
  ~QuietStderr() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

Image read_input(const std::string& path) {
  try {
    Image img = [&] {
      QuietStderr quiet;
      return read_image(path);
    }();
    if (img.width < 1 || img.height < 1 || img.channels.empty())
      fail_input("image has no pixels", path);
    return img;
  } catch (const Error& e) {
    rethrow_as(e, {});
  }
}

void check_args(const CompareArgs& a, Metric metric) {
  if (!std::isfinite(a.pixel_threshold) || a.pixel_threshold < 0.0)
    fail_input("must be a finite number >= 0", {}, 0, "--pixel-threshold");
  if (!a.threshold_set) return;
  // PSNR may be "inf" (require identical images); the others are fractions of 1.
  const bool ok = metric == Metric::psnr ? !std::isnan(a.threshold)
                                         : (std::isfinite(a.threshold) && a.threshold >= 0.0);
  if (!ok)
    fail_input("invalid threshold for metric " + std::string(metric_name(metric)), {}, 0, "--threshold",
               metric == Metric::psnr ? "a PSNR in dB, e.g. 40" : "a finite number >= 0, e.g. 0.004");
}

void check_warn(const CompareArgs& a, Metric metric, double threshold) {
  if (!a.warn_set) return;
  if (!warn_level_valid(metric, threshold, a.warn))
    fail_input("warn level is past the threshold", {}, 0, "--warn",
               metric == Metric::psnr ? "for psnr, --warn >= --threshold (a warning comes before a failure)"
                                      : "for this metric, --warn <= --threshold");
}

struct Verdict {
  Metric metric = Metric::psnr;
  double threshold = 0.0;
  double value = 0.0;
  bool pass = true;
  Outcome outcome = Outcome::pass;
  std::optional<double> warn;
};

std::string channel_name(const Image& img, int c) {
  return c >= 0 && c < img.nchannels() ? img.channels[c] : std::to_string(c);
}

// nlohmann writes inf and NaN as null ("psnr": null means identical images
// unless nonfinite_a/b say otherwise) and doubles in round-trip form, so a
// value printed here can be fed back as a threshold that passes exactly.
void print_json(const CompareArgs& a, const Image& ia, const CompareMetrics& m, const Verdict& v) {
  nlohmann::ordered_json j;
  j["a"] = a.a;
  j["b"] = a.b;
  j["width"] = m.width;
  j["height"] = m.height;
  j["channels"] = m.channels;
  j["identical"] = m.identical();
  j["psnr"] = m.psnr;
  j["mae"] = m.mean_abs;
  j["max"] = m.max_abs;
  j["max_at"] = {{"x", m.max_x}, {"y", m.max_y}, {"channel", channel_name(ia, m.max_channel)}};
  j["pixel_threshold"] = m.pixel_threshold;
  j["pixels_over"] = m.pixels_over;
  j["pixels"] = m.pixels;
  j["fraction"] = m.fraction_over;
  j["flip"] = m.flip_mean;
  j["flip_max"] = m.flip_max;
  j["nonfinite_a"] = m.nonfinite_a;
  j["nonfinite_b"] = m.nonfinite_b;
  j["metric"] = metric_name(v.metric);
  j["threshold"] = v.threshold;
  j["warn"] = v.warn ? nlohmann::ordered_json(*v.warn) : nlohmann::ordered_json(nullptr);
  j["pass"] = v.pass;
  j["outcome"] = outcome_name(v.outcome);
  j["diff"] = a.diff.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(a.diff);
  std::printf("%s\n", j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
}

// 8-bit levels alongside fractions: "0.5/255" reads at a glance.
std::string levels(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g (%.2f/255)", v, v * 255.0);
  return buf;
}

std::string psnr_text(const CompareMetrics& m) {
  if (m.identical()) return "inf dB (identical)";
  if (std::isnan(m.psnr)) return "nan";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2f dB", m.psnr);
  return buf;
}

std::string value_text(Metric metric, double v) {
  if (metric != Metric::psnr) return printf_number("%.6g", v);
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return printf_number("%.2f dB", v);
}

void print_text(const CompareArgs& a, const Image& ia, const CompareMetrics& m, const Verdict& v) {
  std::printf("compare %s %s (%dx%d, %d channels)\n", a.a.c_str(), a.b.c_str(), m.width, m.height, m.channels);
  std::printf("  psnr      %s\n", psnr_text(m).c_str());
  std::printf("  mae       %s\n", levels(m.mean_abs).c_str());
  std::printf("  max       %s at x=%d y=%d %s\n", levels(m.max_abs).c_str(), m.max_x, m.max_y,
              channel_name(ia, m.max_channel).c_str());
  std::printf("  fraction  %.6g (%lld of %lld pixels differ by more than %.4g)\n", m.fraction_over,
              static_cast<long long>(m.pixels_over), static_cast<long long>(m.pixels), m.pixel_threshold);
  if (!std::isnan(m.flip_mean))
    std::printf("  flip      %.6g mean, %.6g max (LDR-FLIP at %.1f pixels per degree)\n", m.flip_mean, m.flip_max,
                flip_default_ppd());
  if (m.nonfinite_a + m.nonfinite_b > 0)
    std::printf("  nonfinite A %lld, B %lld NaN/Inf values (always a failure)\n",
                static_cast<long long>(m.nonfinite_a), static_cast<long long>(m.nonfinite_b));
  if (!a.diff.empty()) std::printf("  diff      %s\n", a.diff.c_str());
  const char* op = v.metric == Metric::psnr ? (v.pass ? ">=" : "<") : (v.pass ? "<=" : ">");
  std::printf("%s: %s %s %s %s", v.outcome == Outcome::warn ? "WARN" : v.pass ? "pass" : "FAIL",
              metric_name(v.metric), value_text(v.metric, v.value).c_str(), op,
              value_text(v.metric, v.threshold).c_str());
  if (v.outcome == Outcome::warn) std::printf(", past the warn level %s", value_text(v.metric, *v.warn).c_str());
  std::printf("\n");
}

int compare(const CompareArgs& a, ExitCodes codes) {
  const Metric metric = a.metric;
  check_args(a, metric);
  check_warn(a, metric, a.threshold_set ? a.threshold : default_threshold(metric));
  if (!a.diff.empty()) {
    try {
      check_output_path(a.diff);  // before any work, as render does
    } catch (const Error& e) {
      rethrow_as(e, "--diff");
    }
    // A slip of the keyboard must not overwrite the reference with a heat map.
    std::error_code ec;
    for (const std::string& input : {a.a, a.b})
      if (std::filesystem::equivalent(a.diff, input, ec))
        fail_input("would overwrite the input image " + input, a.diff, 0, "--diff");
  }
  const Image ia = read_input(a.a);
  const Image ib = read_input(a.b);
  // Name the files here: compare_images() knows only the pixels.
  if (ia.width != ib.width || ia.height != ib.height)
    fail_input("image size " + std::to_string(ib.width) + "x" + std::to_string(ib.height) + " differs from " +
                   a.a + " (" + std::to_string(ia.width) + "x" + std::to_string(ia.height) + ")",
               a.b);
  if (ia.nchannels() != ib.nchannels())
    fail_input(std::to_string(ib.nchannels()) + " channels, but " + a.a + " has " +
                   std::to_string(ia.nchannels()),
               a.b);

  CompareOptions opts;
  opts.pixel_threshold = static_cast<float>(a.pixel_threshold);
  // Every metric every time; FLIP, which compares display values, for images of three channels or more.
  if (ia.nchannels() >= 3) opts.flip_ppd = flip_default_ppd();
  const CompareMetrics m = compare_images(ia, ib, opts);
  Verdict v;
  v.metric = metric;
  v.threshold = a.threshold_set ? a.threshold : default_threshold(metric);
  v.value = metric_value(m, metric);
  v.pass = within_threshold(m, metric, v.threshold);
  if (a.warn_set) v.warn = a.warn;
  v.outcome = classify(m, metric, v.threshold, v.warn);

  // Written on failure too: that is when a person wants to look at it.
  if (!a.diff.empty()) {
    try {
      write_image(diff_heatmap(ia, ib), a.diff,
                  {{"Software", kSoftware},
                   {"ImageDescription", "|A-B| heat map (inferno, top = max abs error " +
                                            std::to_string(m.max_abs) + "): " + a.a + " vs " + a.b}});
    } catch (const Error& e) {
      rethrow_as(e, "--diff");
    }
  }
  if (a.json) print_json(a, ia, m, v);
  else print_text(a, ia, m, v);
  std::fflush(stdout);
  if (m.nonfinite_a + m.nonfinite_b > 0) {
    std::fprintf(stderr, "marchstudio: %s: NaN/Inf values (%lld in A, %lld in B) always fail a comparison\n",
                 a.b.c_str(), static_cast<long long>(m.nonfinite_a), static_cast<long long>(m.nonfinite_b));
    return exit_code_for(codes, Outcome::fail);
  }
  if (!v.pass) {
    std::fprintf(stderr, "marchstudio: %s: %s %s is %s the threshold %s%s\n", a.b.c_str(), metric_name(metric),
                 value_text(metric, v.value).c_str(), metric == Metric::psnr ? "below" : "above",
                 value_text(metric, v.threshold).c_str(),
                 a.threshold_set ? "" : " (no --threshold: the images must be identical)");
    return exit_code_for(codes, Outcome::fail);
  }
  if (v.outcome == Outcome::warn)
    std::fprintf(stderr, "marchstudio: %s: warning: %s %s is past the warn level %s\n", a.b.c_str(),
                 metric_name(metric), value_text(metric, v.value).c_str(), value_text(metric, *v.warn).c_str());
  return exit_code_for(codes, v.outcome);
}

}  // namespace

int run_compare(const CompareArgs& a) {
  return run_with_exit_codes(a.exit_codes, [&] { return compare(a, a.exit_codes); });
}

}  // namespace ms
