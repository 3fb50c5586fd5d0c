#include "suite/suite_report.h"

#include <cmath>
#include <cstdio>
#include <ctime>

#include <nlohmann/json.hpp>

#include "core/format.h"
#include "core/utf8.h"

namespace ms {

namespace {

using Json = nlohmann::ordered_json;

std::string metric_text(Metric m, double v) {
  if (std::isnan(v)) return "nan";
  if (m == Metric::psnr) {
    if (std::isinf(v)) return v > 0 ? "inf dB" : "-inf dB";
    return printf_number("%.2f dB", v);
  }
  if (m == Metric::fraction || m == Metric::flip) return format_value(v);
  return format_value(v) + " (" + printf_number("%.2f", v * 255.0) + "/255)";
}

struct Counts {
  int pass = 0, warn = 0, fail = 0, error = 0;
};

Counts count(const SuiteResult& r) {
  Counts c;
  for (const CaseResult& k : r.cases) {
    if (k.outcome == Outcome::pass) ++c.pass;
    if (k.outcome == Outcome::warn) ++c.warn;
    if (k.outcome == Outcome::fail) ++c.fail;
    if (k.outcome == Outcome::error) ++c.error;
  }
  return c;
}

Json or_null(const std::string& s) { return s.empty() ? Json(nullptr) : Json(s); }

Json case_json(const CaseResult& r) {
  const SuiteCase& c = *r.spec;
  Json j;
  j["name"] = c.name;
  j["outcome"] = outcome_name(r.outcome);
  j["message"] = r.message;
  j["input"] = c.input.string();
  j["reference"] = or_null(c.reference.string());
  j["backend"] = r.backend.empty() ? std::string(backend_name(c.backend)) : r.backend;
  j["gl_renderer"] = or_null(r.renderer);
  j["width"] = r.width;
  j["height"] = r.height;
  j["frames"] = r.frames;
  j["seconds"] = r.seconds;
  Json checks = Json::array();
  for (const CheckResult& k : r.checks) {
    Json e;
    e["metric"] = metric_name(k.check.metric);
    e["value"] = k.value;  // inf (identical) and nan are written as null
    e["threshold"] = k.check.threshold;
    e["warn"] = k.check.warn ? Json(*k.check.warn) : Json(nullptr);
    e["pixel_threshold"] = k.check.pixel_threshold;
    e["outcome"] = outcome_name(k.outcome);
    e["frame"] = k.frame >= 0 ? Json(k.frame) : Json(nullptr);
    e["identical"] = k.metrics.identical();
    e["psnr"] = k.metrics.psnr;
    e["mae"] = k.metrics.mean_abs;
    e["max"] = k.metrics.max_abs;
    e["fraction"] = k.metrics.fraction_over;
    e["flip"] = k.metrics.flip_mean;  // null unless the check is flip
    e["nonfinite"] = k.metrics.nonfinite_b;
    checks.push_back(std::move(e));
  }
  j["checks"] = std::move(checks);
  if (r.cost) {
    const BenchCost& k = *r.cost;
    auto stats = [](const CountStats& s) { return Json{{"mean", s.mean}, {"p99", s.p99}, {"max", s.max}}; };
    j["cost"] = {{"pixels", k.pixels},
                 {"primary_steps", stats(k.primary_steps)},
                 {"shadow_steps", stats(k.shadow_steps)},
                 {"reflection_steps", stats(k.reflection_steps)},
                 {"sdf_evals", stats(k.sdf_evals)},
                 {"step_cap_fraction", k.step_cap_fraction},
                 {"hit_fraction", k.hit_fraction},
                 {"nonfinite_pixels", k.nonfinite_pixels}};
    if (k.primitive_evals) j["cost"]["primitive_evals"] = stats(*k.primitive_evals);
  } else {
    j["cost"] = nullptr;
  }
  if (r.frame_time)
    j["frame_time"] = {{"case_ms", r.frame_time->case_ms},
                       {"calibration_ms", r.frame_time->calibration_ms},
                       {"ratio", r.frame_time->ratio},
                       {"clock", r.frame_time->clock}};
  else
    j["frame_time"] = nullptr;
  Json budgets = Json::array();
  for (const BudgetResult& b : r.budgets)
    budgets.push_back({{"name", b.name}, {"value", b.value}, {"bound", b.bound}, {"outcome", outcome_name(b.outcome)},
                       {"note", b.note}});
  j["budgets"] = std::move(budgets);
  j["deterministic"] = r.nondeterministic_values ? Json{{"differing_values", *r.nondeterministic_values}} : Json(nullptr);
  Json updated = Json::array();
  for (const Updated& u : r.updated) updated.push_back({{"path", u.path.string()}, {"why", u.why}});
  j["updated"] = std::move(updated);
  j["images"] = {{"reference", or_null(r.image_reference)},
                 {"result", or_null(r.image_result)},
                 {"diff", or_null(r.image_diff)}};
  return j;
}

std::string attr(const std::string& name, const std::string& value) {
  return " " + name + "=\"" + xml_escape(value) + "\"";
}

std::string seconds_text(double s) { return printf_number("%.3f", s); }

std::string utc_timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

// Every figure of a case as plain lines, for <system-out>.
std::string details(const CaseResult& r) {
  std::string out = std::string(outcome_name(r.outcome)) + ": " + r.message + "\n";
  out += "input " + r.spec->input.string() + ", " + std::to_string(r.width) + "x" + std::to_string(r.height) + ", " +
         (r.backend.empty() ? std::string(backend_name(r.spec->backend)) : r.backend) + (r.renderer.empty() ? "" : ", " + r.renderer) + "\n";
  for (const CheckResult& k : r.checks) out += "check " + check_text(k) + " [" + outcome_name(k.outcome) + "]\n";
  for (const BudgetResult& b : r.budgets) out += "budget " + b.note + " [" + outcome_name(b.outcome) + "]\n";
  if (r.nondeterministic_values)
    out += "deterministic: " + std::to_string(*r.nondeterministic_values) + " values differ between two renders\n";
  for (const Updated& u : r.updated) out += "updated " + u.path.string() + " (" + u.why + ")\n";
  return out;
}

}  // namespace

std::string format_value(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return printf_number("%.6g", v);
}

std::string check_text(const CheckResult& r) {
  const Metric m = r.check.metric;
  const bool psnr = m == Metric::psnr;
  const bool passed = r.outcome != Outcome::fail && r.outcome != Outcome::error;
  std::string s = std::string(metric_name(m)) + " " + metric_text(m, r.value);
  if (psnr && r.metrics.identical() && r.outcome == Outcome::pass) s += " (identical)";
  s += std::string(" ") + (psnr ? (passed ? ">=" : "<") : (passed ? "<=" : ">")) + " " +
       metric_text(m, r.check.threshold);
  if (r.outcome == Outcome::warn) s += std::string(", past the warn level ") + metric_text(m, *r.check.warn);
  if (r.metrics.nonfinite_a + r.metrics.nonfinite_b > 0) s += ", NaN/Inf values present";
  if (r.frame >= 0) s += " at frame " + std::to_string(r.frame);
  return s;
}

const char* outcome_label(Outcome o) {
  switch (o) {
    case Outcome::pass: return "pass";
    case Outcome::warn: return "WARN";
    case Outcome::fail: return "FAIL";
    case Outcome::error: return "ERROR";
  }
  return "?";
}

std::string case_line(const CaseResult& r) {
  char head[160];
  std::snprintf(head, sizeof head, "%-5s %-28s ", outcome_label(r.outcome), r.spec->name.c_str());
  return head + r.message + " (" + printf_number("%.2f", r.seconds) + " s)";
}

std::string summary_line(const SuiteResult& r) {
  const Counts c = count(r);
  char buf[200];
  std::snprintf(buf, sizeof buf, "%zu case%s: %d passed, %d warned, %d failed, %d could not run (%.1f s)",
                r.cases.size(), r.cases.size() == 1 ? "" : "s", c.pass, c.warn, c.fail, c.error, r.seconds);
  return buf;
}

std::string suite_json(const Suite& suite, const SuiteResult& r) {
  const Counts c = count(r);
  Json j;
  j["schema"] = kTestSchema;
  j["suite"] = {{"file", suite.file.string()}, {"name", suite.name}, {"calibration", or_null(suite.calibration)}};
  Json machines = Json::array();
  for (const auto& [backend, renderer] : r.machines) machines.push_back({{"backend", backend}, {"gl_renderer", renderer}});
  j["machines"] = std::move(machines);
  j["summary"] = {{"cases", r.cases.size()}, {"pass", c.pass}, {"warn", c.warn},    {"fail", c.fail},
                  {"error", c.error},        {"outcome", outcome_name(r.worst())}, {"seconds", r.seconds}};
  Json cases = Json::array();
  for (const CaseResult& k : r.cases) cases.push_back(case_json(k));
  j["cases"] = std::move(cases);
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";  // bytes not UTF-8: U+FFFD
}

std::string suite_junit(const Suite& suite, const SuiteResult& r) {
  const Counts c = count(r);
  const std::string totals = attr("tests", std::to_string(r.cases.size())) + attr("failures", std::to_string(c.fail)) +
                             attr("errors", std::to_string(c.error)) + attr("skipped", "0") +
                             attr("time", seconds_text(r.seconds));
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += "<testsuites" + attr("name", "marchstudio test") + totals + ">\n";
  x += "  <testsuite" + attr("name", suite.name) + totals + attr("timestamp", utc_timestamp()) +
       attr("file", suite.file.string()) + ">\n";
  x += "    <properties>\n";
  for (const auto& [backend, renderer] : r.machines)
    x += "      <property" + attr("name", "gl_renderer." + backend) + attr("value", renderer) + "/>\n";
  x += "    </properties>\n";
  for (const CaseResult& k : r.cases) {
    x += "    <testcase" + attr("name", k.spec->name) + attr("classname", suite.name) +
         attr("time", seconds_text(k.seconds)) + attr("file", k.spec->input.string()) + ">\n";
    x += "      <properties>\n";
    x += "        <property" + attr("name", "outcome") + attr("value", outcome_name(k.outcome)) + "/>\n";
    for (const CheckResult& ch : k.checks)
      x += "        <property" + attr("name", metric_name(ch.check.metric)) + attr("value", format_value(ch.value)) +
           "/>\n";
    for (const BudgetResult& b : k.budgets)
      x += "        <property" + attr("name", b.name) + attr("value", format_value(b.value)) + "/>\n";
    x += "      </properties>\n";
    if (k.outcome == Outcome::fail)
      x += "      <failure" + attr("message", k.message) + attr("type", "threshold") + ">" + xml_escape(details(k)) +
           "</failure>\n";
    if (k.outcome == Outcome::error)
      x += "      <error" + attr("message", k.message) +
           attr("type", k.error_code == Exit::system ? "system" : "bad_input") + ">" + xml_escape(details(k)) +
           "</error>\n";
    x += "      <system-out>" + xml_escape(details(k)) + "</system-out>\n";
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

std::string xml_escape(const std::string& raw) {
  // Bytes that are not UTF-8 (a driver log quoting a shader's bytes) would
  // make the whole document ill-formed: U+FFFD instead. So would U+FFFE and
  // U+FFFF, which are UTF-8 but not XML characters.
  std::string text = valid_utf8(raw);
  for (std::size_t at = 0; (at = text.find("\xef\xbf", at)) != std::string::npos; at += 3)
    if (at + 2 < text.size() && (text[at + 2] == '\xbe' || text[at + 2] == '\xbf')) text[at + 2] = '\xbd';
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (u < 0x20 && ch != '\n' && ch != '\t' && ch != '\r') break;  // not allowed in XML 1.0
        out += ch;
    }
  }
  return out;
}

}  // namespace ms
