#include "sweep/sweep_grid.h"

#include <cstdio>
#include <string_view>
#include <variant>

#include "core/error.h"
#include "core/format.h"
#include "scene/quality.h"
#include "scene/quality_fields.h"

namespace ms {
namespace {

std::string num(double v) { return format_number(v); }

// Every [quality] key (scene/quality_fields.h), so a new one is compared too.
bool same(const SweepConfig& a, const SweepConfig& b) {
  for (const Field<Quality>& f : kQualityFields)
    if (!std::visit([&](auto m) { return a.quality.*m == b.quality.*m; }, f.member)) return false;
  return a.tunables == b.tunables;
}

// Collects rows, skipping repeats.
struct Rows {
  std::vector<SweepConfig> out;
  void add(SweepConfig c) {
    for (const SweepConfig& o : out)
      if (same(o, c)) return;
    out.push_back(std::move(c));
  }
};

// The baseline every sweep shows first (scene/quality.h).
constexpr const char* kBaselinePreset = "textbook";

// The [quality] keys that define the tracer: the baseline's and the
// reference's are the preset's whatever the scene says.
bool defines_tracer(std::string_view key) {
  for (std::string_view k : {"max_steps", "max_distance", "hit_tolerance", "hit_epsilon", "omega", "bounds",
                             "analytic_planes"})
    if (key == k) return true;
  return false;
}

// Pixel-footprint tolerance f, or the fixed epsilon when f is 0.
std::string tolerance_label(float f) { return f == 0.0f ? "eps1e-4" : "fp" + num(f); }

}  // namespace

SweepGrid parse_sweep_grid(const std::string& name) {
  if (name == "quick") return SweepGrid::quick;
  if (name == "full") return SweepGrid::full;
  fail_input("unknown grid '" + name + "'", {}, 0, "--grid", "use quick or full");
}

const char* sweep_grid_name(SweepGrid g) { return g == SweepGrid::quick ? "quick" : "full"; }

Quality sweep_preset_quality(const Quality& scene, const std::string& preset) {
  Quality q = with_preset(scene, preset);
  const bool reference = preset == "reference";
  if (preset != "textbook" && !reference) return q;
  const Quality p = preset_quality(preset);
  for (const Field<Quality>& f : kQualityFields)
    if (defines_tracer(f.key) || (reference && f.key == "shadow_steps"))
      std::visit([&](auto m) { q.*m = p.*m; }, f.member);
  return q;
}

std::vector<SweepConfig> sweep_grid(const Quality& scene, SweepGrid grid, const std::string& base_preset) {
  Rows rows;
  // Every preset of the table, the baseline first.
  rows.add({kBaselinePreset, "preset", sweep_preset_quality(scene, kBaselinePreset), {}});
  for (const std::string& p : quality_preset_names())
    if (p != kBaselinePreset) rows.add({p, "preset", sweep_preset_quality(scene, p), {}});
  const Quality base = sweep_preset_quality(scene, base_preset);
  auto vary = [&](const std::string& axis, const std::string& label, auto&& change,
                  std::vector<std::pair<std::string, std::string>> tunables = {}) {
    SweepConfig c{label, axis, base, std::move(tunables)};
    change(c.quality);
    rows.add(std::move(c));
  };

  for (int s : {32, 64, 128}) vary("max_steps", "steps=" + num(s), [&](Quality& q) { q.max_steps = s; });
  for (float f : {0.0f, 0.05f, 0.1f, 0.25f, 0.5f, 1.0f})
    vary("tolerance", "tol=" + tolerance_label(f), [&](Quality& q) {
      q.hit_tolerance = f;
      q.hit_epsilon = 1e-4f;
    });
  for (float w : {1.2f, 1.5f, 1.8f}) vary("omega", "omega=" + num(w), [&](Quality& q) { q.omega = w; });
  vary("geometry", "no-bounds", [](Quality& q) { q.bounds = false; });
  vary("geometry", "planes-marched", [](Quality& q) { q.analytic_planes = false; });
  vary("geometry", "marched", [](Quality& q) { q.bounds = q.analytic_planes = false; });
  vary("max_distance", "maxdist=50", [](Quality& q) { q.max_distance = 50.0f; });
  for (int s : {16, 32, 128}) vary("shadow", "shadow=" + num(s), [&](Quality& q) { q.shadow_steps = s; });
  vary("shadow", "shadow=classic", [](Quality&) {}, {{"SHADOW_ESTIMATOR", "0"}});
  for (const char* m : {"1.0", "2.0"})
    vary("shadow", std::string("shadow_max_step=") + m, [](Quality&) {}, {{"SHADOW_MAX_STEP", m}});
  for (int a : {0, 3, 8}) vary("ao_taps", "ao=" + num(a), [&](Quality& q) { q.ao_taps = a; });
  for (int b : {0, 2}) vary("bounces", "bounces=" + num(b), [&](Quality& q) { q.bounces = b; });
  vary("normal_eps", "neps=fixed1e-3", [](Quality&) {}, {{"NORMAL_EPS_SCALE", "0.0"}, {"NORMAL_EPS_MIN", "1e-3"}});
  vary("normal_eps", "neps=fp1", [](Quality&) {}, {{"NORMAL_EPS_SCALE", "1.0"}});

  if (grid == SweepGrid::full) {
    for (bool analytic : {false, true})
      for (int s : {64, 128, 255})
        for (float f : {0.02f, 0.25f, 1.0f})
          for (float w : {1.0f, 1.25f, 1.5f}) {
            const std::string label = "steps=" + num(s) + " tol=" + tolerance_label(f) + " omega=" + num(w) +
                                      (analytic ? " analytic" : " marched");
            vary("tracer", label, [&](Quality& q) {
              q.max_steps = s;
              q.hit_tolerance = f;
              q.hit_epsilon = 1e-4f;
              q.omega = w;
              q.bounds = q.analytic_planes = analytic;
            });
          }
  }
  return rows.out;
}

std::string tunable(const SweepConfig& c, const std::string& name, const std::string& fallback) {
  for (const auto& [k, v] : c.tunables)
    if (k == name) return v;
  return fallback;
}

std::vector<SweepConfig> cell_size_rows(const Quality& scene, float auto_side, const std::string& base) {
  std::vector<SweepConfig> rows;
  if (auto_side <= 0.0f) return rows;
  for (const float f : {0.5f, 2.0f}) {
    SweepConfig c{"cell=" + std::string(f < 1.0f ? "0.5x" : "2x"), "cell_size", sweep_preset_quality(scene, base), {}};
    c.cell_size = auto_side * f;
    rows.push_back(std::move(c));
  }
  return rows;
}

}  // namespace ms
