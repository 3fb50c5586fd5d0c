// Reading a suite file (suite/suite.h) with the scene loader's helpers
// (scene/toml_read.h): the same file:line:key errors and did-you-means.
#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>

#include "suite/outcome.h"
#include "suite/suite.h"
#include "suite/suite_toml.h"
#include "core/error.h"
#include "io/input_file.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "scene/quality.h"
#include "core/suggest.h"
#include "scene/toml_guard.h"
#include "scene/toml_read.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

const Views kTop = {"suite", "defaults", "case"};
const Views kSuiteKeys = {"name", "calibration", "clock"};
// [defaults] takes every case key but these.
const Views kCaseOnly = {"name", "scene", "shader", "exclude"};
const Views kCaseKeys = {"name",      "scene",         "shader",     "exclude",       "reference", "size",
                         "time",      "frame",         "frames",     "fps",           "spp",       "backend",
                         "renderer",  "preset",        "disable",    "defines",       "allow_include",
                         "specialize", "deterministic", "metric",    "threshold",     "warn",      "pixel_threshold",
                         "check",     "cost",          "frame_time"};
const Views kCheckKeys = {"metric", "threshold", "warn", "pixel_threshold"};

// `frames = "A..B"` (or "A"), the string form of [A, B]: the suite file's
// own syntax, its numbers held to the array form's range.
std::pair<int, int> frames_text(const Reader& r, int line, const std::string& key, const std::string& text) {
  static const std::regex re(R"(^\s*(\d{1,12})\s*(?:\.\.\s*(\d{1,12})\s*)?$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    r.fail(line, key, "invalid frame range " + quote(text), "e.g. frames = \"0..23\" or [0, 23]");
  const long long a = std::stoll(m[1]), b = m[2].matched ? std::stoll(m[2]) : a;
  if (a > kMaxFrame || b > kMaxFrame)
    r.fail(line, key, "frame number over " + std::to_string(kMaxFrame) + " in " + quote(text));
  return {static_cast<int>(a), static_cast<int>(b)};
}
const Views kCostKeys = {"mean_primary_steps", "p99_primary_steps", "mean_map_calls",
                         "p99_map_calls",      "step_cap_fraction", "mean_primitive_evals", "max_slack"};
const Views kTimeKeys = {"max_ratio", "warn_ratio", "frames", "rounds", "warmup"};
const Views kBackends = {"auto", "egl", "osmesa"};
const Views kEffects = {"shadows", "reflections", "ao", "checker-filter", "bloom"};
const Views kMetrics = {"psnr", "mae", "max", "fraction", "flip"};  // Metric's order
const Views kClocks = {"auto", "cpu", "wall"};               // SuiteClock's order

// "'max_ratio' belongs in [case.frame_time]" for a key valid elsewhere.
std::string elsewhere(std::string_view here, std::string_view key) {
  const std::pair<const char*, const Views*> sections[] = {
      {"[[case]]", &kCaseKeys}, {"[[case.check]]", &kCheckKeys}, {"[case.cost]", &kCostKeys},
      {"[case.frame_time]", &kTimeKeys}, {"[suite]", &kSuiteKeys}};
  for (const auto& [name, keys] : sections)
    if (name != here && std::find(keys->begin(), keys->end(), key) != keys->end())
      return quote(key) + " belongs in " + name;
  return {};
}

void check_keys(const Reader& r, const toml::table& t, std::string_view path, const Views& known,
                std::string_view section) {
  r.check_keys(t, path, known, [&](std::string_view key) { return elsewhere(section, key); });
}

Metric read_metric(const Reader& r, const toml::table& t, std::string_view path) {
  std::size_t i = 0;
  r.read_enum(t, path, "metric", kMetrics, i);
  return static_cast<Metric>(i);
}

// metric/threshold/warn/pixel_threshold of one table (a case or a [[case.check]]).
ImageCheck read_check(const Reader& r, const CaseTables& ct, const toml::table* check) {
  auto at = [&](std::string_view key) {
    return check ? std::pair<const toml::table*, std::string>{check->contains(key) ? check : nullptr, ct.path + ".check"}
                 : ct.at(key);
  };
  ImageCheck c;
  if (auto [t, p] = at("metric"); t) c.metric = read_metric(r, *t, p);
  c.threshold = default_threshold(c.metric);
  const bool psnr = c.metric == Metric::psnr;
  const Range range = psnr ? Range::any() : Range::at_least(0);
  if (auto [t, p] = at("threshold"); t) read_double(r, *t, p, "threshold", range, c.threshold, psnr);
  if (auto [t, p] = at("warn"); t) {
    double w = 0;
    read_double(r, *t, p, "warn", range, w, psnr);
    if (!warn_level_valid(c.metric, c.threshold, w))
      r.fail(Reader::line_of(*t, "warn"), join_key(p, "warn"),
             "warn level " + format_number(w) + " is past the threshold " + format_number(c.threshold),
             psnr ? "for psnr, warn >= threshold (a warning comes before a failure)" : "for this metric, warn <= threshold");
    c.warn = w;
  }
  if (auto [t, p] = at("pixel_threshold"); t) {
    double pt = 0;
    read_double(r, *t, p, "pixel_threshold", Range::at_least(0), pt);
    c.pixel_threshold = static_cast<float>(pt);
  }
  return c;
}

CostBudget read_cost(const Reader& r, const CaseTables& t) {
  for (const auto& [tab, p] : {std::pair{t.own, t.path}, std::pair{t.defaults, t.defaults_path}})
    if (tab) check_keys(r, *tab, p, kCostKeys, "[case.cost]");
  CostBudget b;
  std::optional<double>* fields[] = {&b.mean_primary_steps, &b.p99_primary_steps, &b.mean_map_calls,
                                     &b.p99_map_calls, &b.step_cap_fraction, &b.mean_primitive_evals};
  bool any = false;
  for (std::size_t i = 0; i < std::size(fields); ++i) {
    double v = 0;
    const auto [tab, p] = t.at(kCostKeys[i]);
    if (tab && read_double(r, *tab, p, kCostKeys[i], Range::at_least(0), v)) *fields[i] = v, any = true;
  }
  double slack = 0;
  if (const auto [tab, p] = t.at("max_slack"); tab && read_double(r, *tab, p, "max_slack", Range::above(1), slack))
    b.max_slack = slack;
  if (!any) r.fail(t.line(""), t.path, "[case.cost] sets no bound", "e.g. mean_primary_steps = 25");
  return b;
}

TimeBudget read_time(const Reader& r, const CaseTables& t) {
  for (const auto& [tab, p] : {std::pair{t.own, t.path}, std::pair{t.defaults, t.defaults_path}})
    if (tab) check_keys(r, *tab, p, kTimeKeys, "[case.frame_time]");
  TimeBudget b;
  const auto [mt, mp] = t.at("max_ratio");
  if (!mt || !read_double(r, *mt, mp, "max_ratio", Range::above(0), b.max_ratio))
    r.fail(t.line(""), join_key(t.path, "max_ratio"), "missing required key " + quote(join_key(t.path, "max_ratio")),
           "the largest frame time allowed, as a multiple of the calibration case's, e.g. max_ratio = 1.5");
  double w = 0;
  if (const auto [wt, wp] = t.at("warn_ratio"); wt && read_double(r, *wt, wp, "warn_ratio", Range::above(0), w)) {
    if (w > b.max_ratio) r.fail(t.line("warn_ratio"), join_key(wp, "warn_ratio"), "'warn_ratio' is above 'max_ratio'");
    b.warn_ratio = w;
  }
  if (const auto [x, p] = t.at("frames"); x) r.read(*x, p, "frames", Range::closed(1, 1000), b.frames);
  if (const auto [x, p] = t.at("rounds"); x) r.read(*x, p, "rounds", Range::closed(1, 100), b.rounds);
  if (const auto [x, p] = t.at("warmup"); x) r.read(*x, p, "warmup", Range::closed(0, 1000), b.warmup);
  return b;
}

// `value` with {name} and {backend} filled in; any other {...} is an error.
std::string fill(const Reader& r, int line, const std::string& key, std::string value, const std::string& name,
                 const std::string& backend) {
  for (const auto& [field, with] : {std::pair<std::string, std::string>{"{name}", name}, {"{backend}", backend}})
    for (size_t at; (at = value.find(field)) != std::string::npos;) value.replace(at, field.size(), with);
  if (value.find('{') != std::string::npos || value.find('}') != std::string::npos)
    r.fail(line, key, quote(key) + " has an unknown {field}", "only {name} (the input's stem) and {backend} are filled in");
  return value;
}

bool is_glob(const std::string& s) { return fs::path(s).filename().string().find_first_of("*?[") != std::string::npos; }

// The inputs a `scene`/`shader` value names: itself, or every regular file
// its glob (in the file name only) matches, sorted, minus `exclude` stems.
std::vector<fs::path> expand_input(const Reader& r, int line, const std::string& key, const fs::path& base,
                                   const std::string& value, const std::vector<std::string>& exclude) {
  const fs::path p = (base / value).lexically_normal();
  if (!is_glob(value)) return {p};
  const std::string pattern = p.filename().string();
  // A suite in the working directory has an empty base: its folder is ".".
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path f = it->path();
    if (::fnmatch(pattern.c_str(), f.filename().c_str(), FNM_PERIOD) != 0 || !fs::is_regular_file(f, ec)) continue;
    if (std::count(exclude.begin(), exclude.end(), f.stem().string())) continue;
    out.push_back(p.parent_path() / f.filename());
  }
  std::sort(out.begin(), out.end());
  if (out.empty()) r.fail(line, key, "no file matches " + quote(p.string()));
  return out;
}

// A key of the case or its defaults, read when given: true when it was.
template <class... Args>
bool read_key(const Reader& r, const CaseTables& ct, std::string_view key, Args&&... args) {
  const auto [t, p] = ct.at(key);
  return t && r.read(*t, p, key, std::forward<Args>(args)...);
}

// What the case draws: size, time, frame or frames, fps, spp, renderer, preset.
void read_frame_keys(const Reader& r, const CaseTables& ct, SuiteCase& c) {
  std::pair<int, int> size{0, 0};
  if (const auto [t, p] = ct.at("size"); t) read_int_pair(r, *t, p, "size", Range::closed(1, 16384), size);
  c.width = size.first;
  c.height = size.second;
  float time = 0;
  if (read_key(r, ct, "time", Range::any(), time)) c.time = time;
  int frame = 0;
  if (read_key(r, ct, "frame", Range::at_least(0), frame)) c.frame = frame;
  if (const auto [t, p] = ct.at("frames"); t) {
    std::pair<int, int> f;
    if (t->get("frames")->is_string()) {
      std::string text;
      r.read(*t, p, "frames", text);
      f = frames_text(r, ct.line("frames"), join_key(p, "frames"), text);
    } else {
      read_int_pair(r, *t, p, "frames", Range::closed(0, kMaxFrame), f);
    }
    if (f.second < f.first) r.fail(ct.line("frames"), join_key(p, "frames"), "'frames' ends before it starts");
    c.frames = f;
  }
  if (const auto [t, p] = ct.at("fps"); t) read_double(r, *t, p, "fps", Range::above(0), c.fps);
  read_key(r, ct, "spp", Range::closed(1, 1024), c.spp);
  read_key(r, ct, "renderer", c.renderer);
  if (read_key(r, ct, "preset", c.preset)) {
    const auto& names = quality_preset_names();
    if (std::find(names.begin(), names.end(), c.preset) == names.end()) {
      const Views views(names.begin(), names.end());
      const auto [t, p] = ct.at("preset");
      r.fail(ct.line("preset"), join_key(p, "preset"), "unknown value " + quote(c.preset) + " for 'preset'",
             did_you_mean(c.preset, views).empty() ? "use fast, balanced, reference or textbook" : did_you_mean(c.preset, views));
    }
  }
}

// How the case loads: disable, defines, allow_include, specialize, deterministic.
void read_load_keys(const Reader& r, const CaseTables& ct, const fs::path& base, SuiteCase& c) {
  if (const auto [t, p] = ct.at("disable"); t) c.disable = read_strings(r, *t, p, "disable", kEffects);
  if (const auto [t, p] = ct.at("defines"); t) {
    const toml::table* d = r.table(*t, p, "defines");
    static const std::regex ident(R"(^[A-Za-z_][A-Za-z0-9_]*$)");
    for (auto&& [k, v] : *d) {
      const std::string key = join_key(p, "defines." + std::string(k.str()));
      if (!std::regex_match(std::string(k.str()), ident))
        r.fail(static_cast<int>(k.source().begin.line), key, quote(k.str()) + " is not a GLSL identifier");
      std::string value;
      if (const auto* s = v.as_string()) value = s->get();
      else if (const auto* i = v.as_integer()) value = std::to_string(i->get());
      else r.fail(v, key, quote(key) + " must be a string or an integer", "write a float as a string: \"0.5\"");
      if (const std::string problem = define_value_problem(value); !problem.empty()) r.fail(v, key, quote(key) + " " + problem);
      c.defines.emplace_back(std::string(k.str()), value);
    }
  }
  if (const auto [t, p] = ct.at("allow_include"); t)
    for (const std::string& d : read_strings(r, *t, p, "allow_include")) {
      const fs::path dir = (base / d).lexically_normal();
      std::error_code ec;
      if (!fs::is_directory(dir, ec))
        r.fail(ct.line("allow_include"), join_key(p, "allow_include"), quote(dir.string()) + " is not a directory");
      c.allow_include.push_back(fs::canonical(dir, ec));
    }
  read_key(r, ct, "specialize", Range::any(), c.specialize);
  read_key(r, ct, "deterministic", Range::any(), c.deterministic);
}

// What the case checks: the image checks against `reference`, the cost and
// frame-time budgets; a case must check something.
void read_check_keys(const Reader& r, const CaseTables& ct, SuiteCase& c, std::string& reference) {
  read_key(r, ct, "reference", reference);
  const bool case_check = ct.at("metric").first || ct.at("threshold").first || ct.at("warn").first ||
                          ct.at("pixel_threshold").first;
  std::vector<const toml::table*> checks;
  if (const auto [t, p] = ct.at("check"); t) checks = r.tables(*t, p, "check");
  if (case_check || checks.empty()) c.checks.push_back(read_check(r, ct, nullptr));
  for (std::size_t i = 0; i < checks.size(); ++i) {
    check_keys(r, *checks[i], ct.path + ".check[" + std::to_string(i) + "]", kCheckKeys, "[[case.check]]");
    c.checks.push_back(read_check(r, ct, checks[i]));
  }
  if (const CaseTables cost = ct.sub(r, "cost"); cost.any()) c.cost = read_cost(r, cost);
  if (const CaseTables time = ct.sub(r, "frame_time"); time.any()) c.time_budget = read_time(r, time);
  if (reference.empty()) {
    if (case_check || !checks.empty())
      r.fail(ct.line(case_check ? "metric" : "check"), ct.path + ".reference", "image checks need a 'reference'");
    c.checks.clear();
    if (!c.cost && !c.time_budget)
      r.fail(c.line, ct.path, "the case checks nothing",
             "give it a reference image, a [case.cost] or a [case.frame_time] budget");
  }
}

// One expanded case's reference, its {name} and {backend} filled in, and
// checked against the case: a format that exists, a frame field only for
// an animated case, no EXR for flip.
void set_reference(const Reader& r, const CaseTables& ct, const fs::path& base, const std::string& reference,
                   const std::string& be, SuiteCase& e) {
  const int line = ct.line("reference");
  const std::string key = ct.path + ".reference";
  e.reference = (base / fill(r, line, key, reference, e.input.stem().string(), be)).lexically_normal();
  try {
    image_format_for(e.reference);
    if (e.animated()) FramePattern{e.reference.string()};
  } catch (const Error& err) {
    r.fail(line, key, err.info().what, err.info().hint);
  }
  if (!e.animated() && has_frame_field(e.reference.filename().string()))
    r.fail(line, key, "the reference has a frame field but the case has no 'frames'");
  const bool flip =
      std::any_of(e.checks.begin(), e.checks.end(), [](const ImageCheck& k) { return k.metric == Metric::flip; });
  if (flip && !is_display_format(image_format_for(e.reference)))
    r.fail(line, key, "flip compares display images, and an EXR reference holds linear values",
           "use a .png reference for flip (HDR-FLIP is not implemented)");
}

// One [[case]] table, expanded over its glob and its backend list.
void read_case(const Reader& r, const toml::table& own, const toml::table* defaults, std::size_t index,
               const fs::path& base, std::vector<SuiteCase>& out) {
  CaseTables ct{&own, defaults, "case[" + std::to_string(index) + "]"};
  check_keys(r, own, ct.path, kCaseKeys, "[[case]]");
  const bool has_scene = own.contains("scene"), has_shader = own.contains("shader");
  if (has_scene == has_shader)
    r.fail(Reader::line_of(own, has_shader ? "shader" : ""), ct.path,
           has_scene ? "'scene' and 'shader' exclude each other" : "a case needs 'scene' or 'shader'",
           "scene = \"scenes/x.toml\" or shader = \"x.glsl\": anything `marchstudio render` takes");
  const std::string input_key = has_scene ? "scene" : "shader";
  std::string input, name_template = "{name}";
  r.read(own, ct.path, input_key, input);
  r.read(own, ct.path, "name", name_template);
  const std::vector<std::string> exclude = read_strings(r, own, ct.path, "exclude");
  if (!exclude.empty() && !is_glob(input))
    r.fail(ct.line("exclude"), ct.path + ".exclude", "'exclude' needs a glob in '" + input_key + "'");

  SuiteCase c;
  c.line = Reader::line_of(own);
  read_frame_keys(r, ct, c);
  read_load_keys(r, ct, base, c);
  std::string reference;
  read_check_keys(r, ct, c, reference);

  std::vector<std::string> backends = {"auto"};
  if (const auto [t, p] = ct.at("backend"); t) backends = read_strings(r, *t, p, "backend", kBackends);
  if (backends.empty()) r.fail(ct.line("backend"), ct.path + ".backend", "'backend' lists no backend");
  if (backends.size() > 1 && name_template.find("{backend}") == std::string::npos)
    r.fail(ct.line("name"), ct.path + ".name", "several backends need {backend} in the case name",
           "e.g. name = \"" + name_template + ".{backend}\"");
  const std::vector<fs::path> inputs = expand_input(r, Reader::line_of(own, input_key), ct.path + "." + input_key,
                                                    base, input, exclude);
  if (inputs.size() > 1 && name_template.find("{name}") == std::string::npos)
    r.fail(ct.line("name"), ct.path + ".name", "a glob needs {name} in the case name", "e.g. name = \"{name}\"");
  static const std::regex name_ok(R"(^[A-Za-z0-9_.-]{1,100}$)");
  for (const fs::path& in : inputs)
    for (const std::string& be : backends) {
      SuiteCase e = c;
      e.input = in;
      e.backend = parse_backend(be);  // one of kBackends, checked above
      e.name = fill(r, ct.line("name"), ct.path + ".name", name_template, in.stem().string(), be);
      if (!std::regex_match(e.name, name_ok))
        r.fail(ct.line("name"), ct.path + ".name", "case name " + quote(e.name) + " is not [A-Za-z0-9_.-]{1,100}",
               "it names the report's image files");
      if (!reference.empty()) set_reference(r, ct, base, reference, be, e);
      out.push_back(std::move(e));
    }
}

}  // namespace

const SuiteCase* Suite::find(std::string_view n) const {
  for (const SuiteCase& c : cases)
    if (c.name == n) return &c;
  return nullptr;
}

Suite parse_suite(std::string_view text, const fs::path& display_path) {
  const Reader r(display_path.string());
  check_toml_key_depth(text, r.file());
  toml::table root;
  try {
    root = toml::parse(text, std::string_view{r.file()});
  } catch (const toml::parse_error& e) {
    r.fail(static_cast<int>(e.source().begin.line), {}, "invalid TOML: " + printable(e.description(), 200));
  }
  check_keys(r, root, {}, kTop, "");
  Suite s;
  s.file = display_path;
  s.name = display_path.stem().string();
  const fs::path base = display_path.parent_path();
  const toml::table* st = r.table(root, {}, "suite");
  if (st) {
    check_keys(r, *st, "suite", kSuiteKeys, "[suite]");
    r.read(*st, "suite", "name", s.name);
    r.read(*st, "suite", "calibration", s.calibration);
    r.read_enum(*st, "suite", "clock", kClocks, s.clock);
  }
  const toml::table* defaults = r.table(root, {}, "defaults");
  if (defaults) {
    Views keys;
    for (std::string_view k : kCaseKeys)
      if (std::find(kCaseOnly.begin(), kCaseOnly.end(), k) == kCaseOnly.end()) keys.push_back(k);
    check_keys(r, *defaults, "defaults", keys, "[[case]]");
  }
  const auto cases = r.tables(root, {}, "case");
  if (cases.empty()) r.fail(0, "case", "the suite has no [[case]]", "see docs/testing.md for a minimal suite");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::size_t before = s.cases.size();
    read_case(r, *cases[i], defaults, i, base, s.cases);
    for (std::size_t j = before; j < s.cases.size(); ++j)
      for (std::size_t k = 0; k < j; ++k)
        if (s.cases[k].name == s.cases[j].name)
          r.fail(s.cases[j].line, "case[" + std::to_string(i) + "].name", "duplicate case name " + quote(s.cases[j].name),
                 "the case at line " + std::to_string(s.cases[k].line) + " has it already");
  }
  const bool timed = std::any_of(s.cases.begin(), s.cases.end(), [](const SuiteCase& c) { return c.time_budget; });
  if (!s.calibration.empty() && !s.find(s.calibration)) {
    Views names;
    for (const SuiteCase& c : s.cases) names.push_back(c.name);
    r.fail(Reader::line_of(*st, "calibration"), "suite.calibration", "no case is named " + quote(s.calibration),
           did_you_mean(s.calibration, names));
  }
  if (timed && s.calibration.empty()) {
    const auto it = std::find_if(s.cases.begin(), s.cases.end(), [](const SuiteCase& c) { return c.time_budget; });
    r.fail(it->line, "suite.calibration", "frame-time budgets need a calibration case",
           "add [suite] calibration = \"<case name>\": budgets are ratios to its frame time");
  }
  return s;
}

Suite load_suite(const fs::path& path) { return parse_suite(read_input_file(path, "suite file"), path); }

std::vector<const SuiteCase*> select_cases(const Suite& suite, const std::vector<std::string>& patterns) {
  std::vector<const SuiteCase*> out;
  for (const std::string& p : patterns) {
    const bool any = std::any_of(suite.cases.begin(), suite.cases.end(), [&](const SuiteCase& c) {
      return ::fnmatch(p.c_str(), c.name.c_str(), 0) == 0;
    });
    if (!any) fail_input("no case of " + suite.file.string() + " matches '" + p + "'", {}, 0, "--only");
  }
  for (const SuiteCase& c : suite.cases)
    if (patterns.empty() || std::any_of(patterns.begin(), patterns.end(), [&](const std::string& p) {
          return ::fnmatch(p.c_str(), c.name.c_str(), 0) == 0;
        }))
      out.push_back(&c);
  return out;
}

}  // namespace ms
