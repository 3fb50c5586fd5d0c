#include "sweep/sweep_report.h"

#include <cmath>
#include <cstdio>
#include <type_traits>
#include <variant>

#include <nlohmann/json.hpp>

#include "core/format.h"
#include "scene/quality_fields.h"

namespace ms {
namespace {

using Json = nlohmann::ordered_json;

std::string fmt(const char* f, double v) { return printf_number(f, v); }

// CSV cell: %.6g, "inf", or empty for NaN.
std::string cell(double v) {
  if (std::isnan(v)) return "";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt("%.6g", v);
}

// JSON number, null for inf/NaN (nlohmann would write null anyway; explicit).
Json jnum(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

std::string tun(const SweepConfig& c, const char* name, const char* fallback) { return tunable(c, name, fallback); }

// Every [quality] key (scene/quality_fields.h), so a new one is reported too.
Json quality_json(const Quality& q) {
  Json j = Json::object();
  for (const Field<Quality>& f : kQualityFields)
    std::visit(
        [&](auto m) {
          const auto& v = q.*m;
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, glm::vec3>)
            j[std::string(f.key)] = Json::array({v.x, v.y, v.z});
          else
            j[std::string(f.key)] = v;
        },
        f.member);
  return j;
}

Json error_json(const SweepError& e, bool aovs) {
  Json j = {{"psnr", jnum(e.psnr)}, {"mae", jnum(e.mae)}};
  if (aovs) {
    j["depth_mean"] = jnum(e.depth_mean);
    j["depth_max"] = jnum(e.depth_max);
    j["misclassified"] = jnum(e.misclassified);
  }
  return j;
}

}  // namespace

std::string sweep_csv(const SweepResult& r) {
  std::string out =
      "name,axis,max_steps,hit_tolerance,hit_epsilon,omega,max_distance,bounds,analytic_planes,shadow_steps,"
      "shadow_estimator,ao_taps,bounces,normal_eps_scale,normal_eps_min,lipschitz,"
      "gpu_ms,wall_ms,cpu_ms,compile_ms,mean_steps,step_cap_fraction,sdf_evals_mean,"
      "psnr,mae,depth_err_mean,depth_err_max,misclassified,psnr_ss,mae_ss,"
      "exact_psnr,exact_mae,exact_depth_err_mean,exact_depth_err_max,exact_misclassified,pareto,pareto_ss\n";
  for (const SweepRow& row : r.rows) {
    const SweepConfig& c = row.config;
    const Quality& q = c.quality;
    const double nan = std::nan("");
    const SweepError x = row.exact.value_or(SweepError{nan, nan, nan, nan, nan});
    const std::string cells[] = {
        c.name, c.axis, std::to_string(q.max_steps), cell(q.hit_tolerance), cell(q.hit_epsilon), cell(q.omega),
        cell(q.max_distance), q.bounds ? "1" : "0", q.analytic_planes ? "1" : "0", std::to_string(q.shadow_steps),
        tun(c, "SHADOW_ESTIMATOR", "1"), std::to_string(q.ao && q.ao_taps > 0 ? q.ao_taps : 0),
        std::to_string(q.reflections ? q.bounces : 0), tun(c, "NORMAL_EPS_SCALE", "0.5"),
        tun(c, "NORMAL_EPS_MIN", "1e-4"), cell(q.lipschitz), cell(row.gpu_best_median), cell(row.wall_best_median), cell(row.cpu_best_median),
        cell(row.compile_ms), cell(row.cost.primary_steps.mean), cell(row.cost.step_cap_fraction),
        cell(row.cost.sdf_evals.mean), cell(row.same_spp.psnr), cell(row.same_spp.mae), cell(row.same_spp.depth_mean),
        cell(row.same_spp.depth_max), cell(row.same_spp.misclassified), cell(row.supersampled.psnr),
        cell(row.supersampled.mae), cell(x.psnr), cell(x.mae), cell(x.depth_mean), cell(x.depth_max),
        cell(x.misclassified),
        row.pareto_same_spp ? "1" : "0", row.pareto_supersampled ? "1" : "0"};
    std::string line;
    for (const std::string& s : cells) {
      if (!line.empty()) line += ',';
      // Names have no commas or quotes, but a scene might one day; quote defensively.
      line += s.find_first_of(",\"") == std::string::npos ? s : "\"" + s + "\"";
    }
    out += line + "\n";
  }
  return out;
}

std::string sweep_json(const SweepSubject& subject, const SweepSettings& s, const SweepResult& r) {
  Json j;
  j["schema"] = kSweepSchema;
  j["scene"] = {{"file", subject.scene_file}, {"name", subject.scene_name}};
  j["command"] = subject.command;
  j["settings"] = {{"width", s.width},   {"height", s.height}, {"spp", s.spp},       {"ref_spp", s.ref_spp},
                   {"frames", s.frames}, {"rounds", s.rounds}, {"warmup", s.warmup}, {"time", s.time},
                   {"grid", sweep_grid_name(s.grid)}, {"specialize", subject.specialize},
                   {"time_by", sweep_clock_name(s.clock)}, {"dispatch", dispatch_name(r.dispatch)},
                   {"compute_group", r.dispatch == Dispatch::compute ? Json(group_name(s.group)) : Json()}};
  j["machine"] = {{"backend", r.backend},
                  {"gl_renderer", r.gl_renderer},
                  {"gl_vendor", r.gl_vendor},
                  {"gl_version", r.gl_version},
                  {"gpu_timer", r.gpu_timer}};
  j["default_preset"] = "balanced";
  j["baseline"] = "textbook";
  j["references"] = {
      {"same_spp", {{"spp", s.spp}, {"quality", quality_json(r.reference_quality)}}},
      {"supersampled", {{"spp", s.ref_spp}, {"quality", quality_json(r.reference_quality)}}},
      {"exact",
       {{"status", r.exact_status},
        {"image", "each row's own settings with its primary and reflection rays intersected exactly "
                  "(sdf_shaders/exact.glsl), same spp"},
        {"depth", "primary rays through the pixel centres, intersected on the CPU in double"}}}};
  Json rows = Json::array();
  for (const SweepRow& row : r.rows) {
    const SweepConfig& c = row.config;
    Json tun = Json::object();
    for (const auto& [k, v] : c.tunables) tun[k] = v;
    Json jr = {{"name", c.name},
               {"axis", c.axis},
               {"quality", quality_json(c.quality)},
               {"tunables", tun},
               {"cell_size", c.cell_size},
               {"time_ms",
                {{"gpu", row.gpu_best_median},
                 {"wall", row.wall_best_median},
                 {"cpu", row.cpu_best_median},
                 {"front", row_time_ms(r, row)},
                 {"gpu_median_all", row.gpu_ms.median},
                 {"gpu_p95_all", row.gpu_ms.p95},
                 {"wall_median_all", row.wall_ms.median},
                 {"compile", row.compile_ms}}},
               {"cost",
                {{"mean_steps", row.cost.primary_steps.mean},
                 {"p99_steps", row.cost.primary_steps.p99},
                 {"step_cap_fraction", row.cost.step_cap_fraction},
                 {"sdf_evals_mean", row.cost.sdf_evals.mean},
                 {"hit_fraction", row.cost.hit_fraction}}},
               {"error",
                {{"same_spp", error_json(row.same_spp, true)},
                 {"supersampled", error_json(row.supersampled, false)},
                 {"exact", row.exact ? Json{{"psnr", jnum(row.exact->psnr)},
                                            {"mae", jnum(row.exact->mae)},
                                            {"depth_mean", jnum(row.exact->depth_mean)},
                                            {"depth_max", jnum(row.exact->depth_max)},
                                            {"misclassified", jnum(row.exact->misclassified)}}
                                     : Json(nullptr)}}},
               {"pareto", {{"same_spp", row.pareto_same_spp}, {"supersampled", row.pareto_supersampled}}}};
    rows.push_back(std::move(jr));
  }
  j["rows"] = std::move(rows);
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string sweep_table(const SweepSubject& subject, const SweepSettings& s, const SweepResult& r) {
  std::string out = "scene     " + subject.scene_name + " (" + subject.scene_file + ")\n";
  out += "settings  " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", spp " +
         std::to_string(s.spp) + ", " + std::to_string(s.frames) + " timed frames per row in each of " +
         std::to_string(s.rounds) + " rounds (best round's median), grid " +
         sweep_grid_name(s.grid) + ", " + subject.specialize + " shader, " + dispatch_name(r.dispatch) +
         " dispatch\n";
  out += "machine   " + r.backend + ", " + r.gl_renderer + ", " + r.gl_version + "\n";
  out += "reference " + std::to_string(r.reference_quality.max_steps) + " steps, tolerance " +
         fmt("%g", r.reference_quality.hit_tolerance) + " px, epsilon " +
         fmt("%g", r.reference_quality.hit_epsilon) + ", omega 1; same spp and " + std::to_string(s.ref_spp) +
         " spp; exact: " + r.exact_status + "\n\n";
  char buf[512];
  std::snprintf(buf, sizeof buf, "%-40s %9s %9s %7s %7s %7s %7s %9s %7s %7s %7s %9s %7s %5s\n", "config",
                r.gpu_timer ? "gpu ms" : "wall ms", "cpu ms", "steps", "cap%", "PSNR", "MAE/255", "depth", "miss%",
                "PSNRss", "PSNRex", "exact dz", "exmiss%", "front");
  out += buf;
  for (const SweepRow& row : r.rows) {
    const auto ps = [](double v) { return std::isinf(v) ? std::string("inf") : fmt("%.2f", v); };
    const std::string ex_p = row.exact ? ps(row.exact->psnr) : "-";
    const std::string ex_d = row.exact ? fmt("%.2e", row.exact->depth_mean) : "-";
    const std::string ex_m = row.exact ? fmt("%.3f", 100.0 * row.exact->misclassified) : "-";
    std::string front = row.pareto_same_spp ? "A" : "";
    if (row.pareto_supersampled) front += "B";
    std::snprintf(buf, sizeof buf, "%-40s %9.2f %9.2f %7.2f %7.3f %7s %7.3f %9.2e %7.3f %7s %7s %9s %7s %5s\n",
                  row.config.name.substr(0, 40).c_str(), r.gpu_timer ? row.gpu_best_median : row.wall_best_median,
                  row.cpu_best_median, row.cost.primary_steps.mean,
                  100.0 * row.cost.step_cap_fraction, ps(row.same_spp.psnr).c_str(), 255.0 * row.same_spp.mae,
                  row.same_spp.depth_mean, 100.0 * row.same_spp.misclassified, ps(row.supersampled.psnr).c_str(),
                  ex_p.c_str(), ex_d.c_str(), ex_m.c_str(), front.c_str());
    out += buf;
  }
  out += "\nPSNR, MAE, depth, miss%: against the converged reference at the same spp; PSNRss: against the " +
         std::to_string(s.ref_spp) +
         " spp one; PSNRex: against the row's own shading with its rays intersected exactly; exact dz, exmiss%: "
         "primary-ray depth and hit/miss against exact intersection on the CPU. Times: best round's "
         "median per frame; cpu: this process's CPU time (llvmpipe's threads). front: on the " +
         std::string(sweep_clock_name(r.clock)) + " time/PSNR Pareto front (A same spp, B supersampled).\n";
  return out;
}

}  // namespace ms
