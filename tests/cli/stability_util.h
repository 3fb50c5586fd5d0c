// Helpers for tests/cli/test_stability.cpp and test_nan_guard.cpp: render
// a scenes/hard/ scene with every AOV through the real binary, scene
// variants, the stated tolerances
// (tests/cost/stability.toml), and an exact reference: sphere tracing in
// double precision of a C++ twin of the scene's map() (exact fields only),
// converged to 1e-9, which also measures how close each ray passes to a
// surface it misses.
#pragma once
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu_tracer.h"
#include "io/image_io.h"
#include "run.h"
#include "scene/load.h"

namespace ms::test {

namespace fs = std::filesystem;

inline fs::path hard_scene(const std::string& name) { return source_dir() / "scenes" / "hard" / (name + ".toml"); }

// A render's AOVs (every channel), looked up by name.
struct Aovs {
  Image img;
  int ch(const std::string& name) const {
    const auto it = std::find(img.channels.begin(), img.channels.end(), name);
    if (it == img.channels.end()) ADD_FAILURE() << "no channel " << name;
    return it == img.channels.end() ? 0 : static_cast<int>(it - img.channels.begin());
  }
  float at(int x, int y, const std::string& name) const { return img.at(x, y, ch(name)); }
  bool hit(int x, int y) const { return at(x, y, "hit") > 0.5f; }
  int w() const { return img.width; }
  int h() const { return img.height; }
  // Pixels with a NaN or Inf in any channel.
  int nonfinite() const {
    int n = 0;
    for (int y = 0; y < h(); ++y)
      for (int x = 0; x < w(); ++x) {
        bool bad = false;
        for (int c = 0; c < img.nchannels(); ++c) bad = bad || !std::isfinite(img.at(x, y, c));
        n += bad;
      }
    return n;
  }
  double mean(const std::string& name) const {
    double s = 0;
    for (int y = 0; y < h(); ++y)
      for (int x = 0; x < w(); ++x) s += at(x, y, name);
    return s / (static_cast<double>(w()) * h());
  }
  double fraction_over_half(const std::string& name) const {
    int n = 0;
    for (int y = 0; y < h(); ++y)
      for (int x = 0; x < w(); ++x) n += at(x, y, name) > 0.5f;
    return static_cast<double>(n) / (static_cast<double>(w()) * h());
  }
};

constexpr int kW = 160, kH = 90;  // every stability render (the suite must stay fast)

// `marchstudio render TOML --aov <all> -o DIR/OUT --size 160x90 EXTRA...`.
inline Aovs render_aovs(const TempDir& dir, const fs::path& toml, const std::string& out,
                        const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", toml.string(), "--size", std::to_string(kW) + "x" + std::to_string(kH),
                                   "--aov", "depth,normal,steps,material,shadow,ao,cost", "-o",
                                   (dir / out).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << toml << ": " << r.err;
  if (r.exit_code != 0) return {};
  return {read_image(dir / out)};
}

// A copy of scenes/hard/NAME.toml (with its map, which must not #include)
// in `dir`, with each `from` line fragment replaced by `to` (each must occur).
inline fs::path hard_variant(const TempDir& dir, const std::string& name, const std::string& out_name,
                             const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = read_file(hard_scene(name));
  for (const auto& [from, to] : edits) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << name << ".toml has no '" << from << "'";
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const Scene s = load_scene(hard_scene(name));
  write_file(dir / s.map_file.filename().string(), read_file(s.map_file));
  const fs::path p = dir / (out_name + ".toml");
  write_file(p, text);
  return p;
}

// tests/cost/stability.toml: the stated tolerances, one table per case.
inline const toml::table& stability_bounds() {
  static const toml::table t = toml::parse_file((source_dir() / "tests/cost/stability.toml").string());
  return t;
}
inline double bound(const std::string& table, const std::string& key) {
  const auto v = stability_bounds()[table][key].value<double>();
  EXPECT_TRUE(v.has_value()) << "tests/cost/stability.toml: no [" << table << "] " << key;
  return v.value_or(0.0);
}

// ---- The exact reference: double-precision sphere tracing of a C++ twin of
// map() (an exact, 1-Lipschitz field), to a 1e-9 relative tolerance.
using glm::dvec3;
using Sdf = std::function<double(const glm::dvec3&)>;

struct RefHit {
  bool hit = false;
  double t = 0;           // distance to the surface along the unit ray
  glm::dvec3 n{0.0};      // exact normal there (central differences, tiny step)
  double closest = 1e30;  // min over the march of d / tol(t): < 1 where the GPU may stop (a tolerance hit)
  double closest_fp = 1e30;  // min of d / footprint(t): < 1 where a ray out of steps may stop (trace.glsl)
};

inline glm::dvec3 ref_normal(const Sdf& f, const glm::dvec3& p, double scale) {
  const double e = 1e-7 * std::max(1.0, scale);
  const glm::dvec3 g(f(p + glm::dvec3(e, 0, 0)) - f(p - glm::dvec3(e, 0, 0)),
                     f(p + glm::dvec3(0, e, 0)) - f(p - glm::dvec3(0, e, 0)),
                     f(p + glm::dvec3(0, 0, e)) - f(p - glm::dvec3(0, 0, e)));
  const double l = glm::length(g);
  return l > 0 ? g / l : glm::dvec3(0, 1, 0);
}

// `tol(t)` is the GPU's hit tolerance at t (cpu_tolerance()).
inline RefHit ref_trace(const CpuRay& r, const Sdf& f, const Quality& q) {
  const glm::dvec3 o(r.o), d = glm::normalize(glm::dvec3(r.d));
  RefHit res;
  double t = 0;
  for (int i = 0; i < 2000000 && t <= q.max_distance; ++i) {
    const double h = f(o + d * t);
    res.closest = std::min(res.closest, h / cpu_tolerance(r, q, t));
    if (t > 0) res.closest_fp = std::min(res.closest_fp, h / std::max<double>(q.hit_epsilon, t * r.spread));
    if (h < 1e-9 * (1.0 + t)) {
      res.hit = true;
      res.t = t;
      res.n = ref_normal(f, o + d * t, glm::length(o) + t);
      return res;
    }
    t += std::max(h, 1e-12 * (1.0 + t));
  }
  return res;
}

// Hit/miss of the GPU against the reference, for pixels whose answer is not
// ambiguous: a ray the reference sees miss but that passes within
// `ambiguity` tolerances of a surface may legitimately stop there.
struct HitCheck {
  int pixels = 0, ref_hits = 0, ambiguous = 0;
  int false_miss = 0, false_hit = 0;  // unambiguous misclassifications
  int depth_checked = 0, depth_bad = 0;
  int silhouette_hits = 0;            // hits on a nearer surface the ray passes within tolerance of
  double worst_depth_ratio = 0;       // max |t_gpu - t_ref| / allowed
  double misclassified() const { return static_cast<double>(false_miss + false_hit) / std::max(pixels, 1); }
};

// Compares every pixel; depth of hits on both sides must be within
// tol(t)/cos(theta) + slack(t) of the reference (theta: the ray's angle to
// the exact normal, cos kept >= 1e-3). `verbose`: prints the first misfits.
inline HitCheck check_hits(const Aovs& a, const Scene& s, const Sdf& f,
                           const std::function<double(double t)>& slack, double ambiguity = 1.5) {
  HitCheck c;
  int printed = 0;
  for (int y = 0; y < a.h(); ++y)
    for (int x = 0; x < a.w(); ++x) {
      const CpuRay ray = cpu_camera_ray(s.camera, a.w(), a.h(), x, y);
      const RefHit ref = ref_trace(ray, f, s.quality);
      const bool gpu = a.hit(x, y), capped = a.at(x, y, "step_cap") > 0.5f;
      ++c.pixels;
      c.ref_hits += ref.hit;
      const bool amb = !ref.hit && (ref.closest < ambiguity || (capped && ref.closest_fp < ambiguity));
      c.ambiguous += amb;
      if (ref.hit && !gpu) ++c.false_miss;
      if (!ref.hit && gpu && !amb) ++c.false_hit;
      if ((ref.hit != gpu && !amb) && printed++ < 5)
        std::printf("  misfit %d,%d ref %s t %.6g closest %.3g, gpu t %.6g steps %g cap %g\n", x, y,
                    ref.hit ? "hit" : "miss", ref.t, ref.closest, a.at(x, y, "Z"), a.at(x, y, "steps"),
                    a.at(x, y, "step_cap"));
      if (ref.hit && gpu) {
        const double t = a.at(x, y, "Z");
        const double cosv = std::max(std::abs(glm::dot(glm::normalize(glm::dvec3(ray.d)), ref.n)), 1e-3);
        // A ray that ran out of steps is a hit within one footprint (trace.glsl).
        const double tol = capped ? std::max<double>(s.quality.hit_epsilon, t * ray.spread)
                                  : cpu_tolerance(ray, s.quality, t);
        const double allowed = tol / cosv + slack(ref.t);
        const double err = std::abs(t - ref.t);
        // Stopped short within the tolerance of another surface the ray
        // passes (a silhouette it grazes on the way): a tolerance hit, not a
        // depth error; the point must lie within that tolerance.
        const dvec3 pg = dvec3(ray.o) + t * glm::normalize(dvec3(ray.d));
        if (err > allowed && t < ref.t && f(pg) <= ambiguity * cpu_tolerance(ray, s.quality, t) + slack(t)) {
          ++c.silhouette_hits;
          continue;
        }
        ++c.depth_checked;
        c.depth_bad += err > allowed;
        if (err > allowed && printed++ < 8)
          std::printf("  depth %d,%d gpu %.6g ref %.6g cos %.3g allowed %.3g mat %g n %g %g %g\n", x, y, t, ref.t, cosv,
                      allowed, a.at(x, y, "material"), ref.n.x, ref.n.y, ref.n.z);
        c.worst_depth_ratio = std::max(c.worst_depth_ratio, err / allowed);
      }
    }
  return c;
}

}  // namespace ms::test
