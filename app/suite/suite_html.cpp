#include "suite/suite_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/compare.h"
#include "suite/suite_report.h"
#include "core/version.h"
#include "io/image_io.h"
#include "io/atomic_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

std::string esc(const std::string& s) { return xml_escape(s); }

// A linear float image (EXR) as display values: clamped, sRGB-encoded, RGB.
// 8-bit images are display values already.
Image for_display(const Image& img, bool linear) {
  Image out;
  out.width = img.width;
  out.height = img.height;
  const int nch = img.nchannels(), keep = std::min(nch, 3);
  out.channels.assign(img.channels.begin(), img.channels.begin() + keep);
  const size_t npix = static_cast<size_t>(img.width) * img.height;
  out.pixels.resize(npix * keep);
  for (size_t p = 0; p < npix; ++p)
    for (int c = 0; c < keep; ++c) {
      float v = img.pixels[p * nch + c];
      v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 1.0f;
      if (linear) v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
      out.pixels[p * keep + c] = v;
    }
  return out;
}

const ImageMetadata kMeta = {{"Software", std::string(kSoftware) + " test --report"}};

// Failures first: could not run, fail, warn, pass; suite order within.
std::vector<const CaseResult*> ordered(const SuiteResult& r) {
  std::vector<const CaseResult*> out;
  for (const CaseResult& c : r.cases) out.push_back(&c);
  std::stable_sort(out.begin(), out.end(), [](const CaseResult* a, const CaseResult* b) { return a->outcome > b->outcome; });
  return out;
}

std::string figure(const std::string& src, const std::string& caption, int w, int h) {
  if (src.empty()) return "<figure class=\"none\"><div class=\"absent\">no " + esc(caption) + "</div><figcaption>" +
                          esc(caption) + "</figcaption></figure>";
  // Small test renders are shown enlarged, pixel for pixel.
  const int scale = w > 0 && w <= 240 ? 2 : 1;
  const int dw = std::min(w * scale, 480), dh = w > 0 ? h * dw / w : h;
  return "<figure><img src=\"" + esc(src) + "\" alt=\"" + esc(caption) + "\" width=\"" + std::to_string(dw) +
         "\" height=\"" + std::to_string(dh) + "\"><figcaption>" + esc(caption) + "</figcaption></figure>";
}

std::string row(const CaseResult& r) {
  const SuiteCase& c = *r.spec;
  const std::string o = outcome_name(r.outcome);
  std::string h = "<tr class=\"case " + o + "\" id=\"case-" + esc(c.name) + "\" data-outcome=\"" + o + "\">\n";
  h += "<td class=\"outcome\"><span class=\"badge " + o + "\">" + esc(outcome_label(r.outcome)) + "</span></td>\n";
  h += "<td class=\"what\"><div class=\"name\">" + esc(c.name) + "</div>";
  if (!r.message_sums_up) h += "<div class=\"message\">" + esc(r.message) + "</div>";
  h += "\n<ul class=\"figures\">";
  for (const CheckResult& k : r.checks)
    h += "<li class=\"" + std::string(outcome_name(k.outcome)) + "\">" + esc(check_text(k)) + "</li>";
  for (const BudgetResult& b : r.budgets)
    h += "<li class=\"" + std::string(outcome_name(b.outcome)) + "\">" + esc(b.note) + "</li>";
  if (r.nondeterministic_values)
    h += std::string("<li class=\"") + (*r.nondeterministic_values ? "fail" : "pass") + "\">" +
         (*r.nondeterministic_values ? std::to_string(*r.nondeterministic_values) + " values differ between two renders"
                                     : "bit-identical in two renders") + "</li>";
  for (const Updated& u : r.updated) h += "<li class=\"warn\">updated " + esc(u.path.string()) + " (" + esc(u.why) + ")</li>";
  h += "</ul>\n<div class=\"input\">" + esc(c.input.string()) + "</div>";
  if (!c.reference.empty()) h += "<div class=\"input\">reference " + esc(c.reference.string()) + "</div>";
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.2f s", r.seconds);
  h += "<div class=\"input\">" + std::to_string(r.width) + "x" + std::to_string(r.height) + ", " +
       esc(r.backend.empty() ? backend_name(c.backend) : r.backend) + (r.renderer.empty() ? "" : ", " + esc(r.renderer)) + ", " +
       secs + "</div></td>\n";
  h += "<td class=\"images\">";
  if (!c.checks.empty())
    h += figure(r.image_reference, "reference", r.width, r.height) + figure(r.image_result, "result", r.width, r.height) +
         figure(r.image_diff, "difference", r.width, r.height);
  h += "</td>\n</tr>\n";
  return h;
}

constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; background: #fafafa; }
h1 { font-size: 1.4em; margin: 0 0 .3em; }
.summary, .machine { color: #555; margin: .2em 0; }
table { border-collapse: collapse; width: 100%; margin-top: 1em; }
td { border-top: 1px solid #ddd; padding: .6em; vertical-align: top; }
td.outcome { width: 5em; } td.images { white-space: nowrap; width: 1%; }
.badge { display: inline-block; min-width: 3.5em; text-align: center; padding: .15em .4em; border-radius: 3px;
         font-weight: bold; color: #fff; }
.badge.pass { background: #2e7d32; } .badge.warn { background: #e69500; }
.badge.fail { background: #c62828; } .badge.error { background: #6a1b9a; }
.name { font-weight: bold; font-family: monospace; font-size: 1.1em; }
.message { margin: .2em 0; } .input { color: #666; font-size: .9em; font-family: monospace; }
figure { display: inline-block; margin: 0 .5em .3em 0; vertical-align: top; }
figure img { image-rendering: pixelated; border: 1px solid #ccc; background: #fff; }
figure img[data-loaded="no"] { outline: 3px solid #c62828; }
figcaption { text-align: center; color: #666; font-size: .85em; }
.absent { border: 1px dashed #bbb; color: #999; padding: 2em 1em; }
ul { margin: .3em 0; padding-left: 1.2em; } li.fail, li.error { color: #c62828; font-weight: bold; } li.warn { color: #b26a00; }
)";

// Marks every image as loaded or not (data-loaded), so a broken one shows
// and a headless browser can tell; the page reads fine without it.
constexpr const char* kScript = R"(
for (const img of document.images) {
  const mark = () => { img.dataset.loaded = img.naturalWidth > 0 ? "yes" : "no"; };
  if (img.complete) mark(); else { img.addEventListener("load", mark); img.addEventListener("error", mark); }
}
)";

}  // namespace

void write_case_images(const fs::path& dir, CaseResult& r, const Image& reference, const Image& result) {
  const SuiteCase& c = *r.spec;
  const bool linear = !c.reference.empty() && !is_display_format(image_format_for(c.reference));
  const std::string stem = c.name;
  auto put = [&](const Image& img, const std::string& kind, std::string& name) {
    name = stem + "." + kind + ".png";
    write_image(img, dir / name, kMeta);
  };
  if (!result.pixels.empty()) put(for_display(result, linear), "result", r.image_result);
  if (!reference.pixels.empty()) put(for_display(reference, linear), "reference", r.image_reference);
  if (!reference.pixels.empty() && !result.pixels.empty() && reference.width == result.width &&
      reference.height == result.height && reference.nchannels() == result.nchannels())
    put(diff_heatmap(reference, result), "diff", r.image_diff);
}

std::string suite_html(const Suite& suite, const SuiteResult& r) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + esc(suite.name) +
                  ": marchstudio test</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
  h += "<h1>" + esc(suite.name) + "</h1>\n";
  h += "<p class=\"summary\" id=\"summary\" data-outcome=\"" + std::string(outcome_name(r.worst())) + "\">" +
       esc(summary_line(r)) + ", " + esc(suite.file.string()) + "</p>\n";
  for (const auto& [backend, renderer] : r.machines)
    h += "<p class=\"machine\">" + esc(backend) + ": " + esc(renderer) + "</p>\n";
  h += "<table id=\"cases\">\n<tbody>\n";
  for (const CaseResult* c : ordered(r)) h += row(*c);
  h += "</tbody>\n</table>\n<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
  return h;
}

void write_html_report(const fs::path& dir, const Suite& suite, const SuiteResult& r) {
  write_text_file(dir / "index.html", suite_html(suite, r), "--report");
}

}  // namespace ms
