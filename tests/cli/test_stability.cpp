// The numerical stability suite (docs/stability.md): every hard
// case in scenes/hard/ rendered by the real binary with the default preset
// (balanced), checked through its AOVs against an exact double-precision
// reference or a converged render. Tolerances live in
// tests/cost/stability.toml, each with the value measured when it was set.
#include <gtest/gtest.h>

#include <cmath>

#include "stability_util.h"

namespace ms::test {
namespace {

using glm::dvec3;

double sd_box(dvec3 p, dvec3 b) {
  const dvec3 q = glm::abs(p) - b;
  return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}
double sd_torus(dvec3 p, double R, double r) { return glm::length(glm::dvec2(glm::length(glm::dvec2(p.x, p.z)) - R, p.y)) - r; }
dvec3 rot_x60(dvec3 q) {  // thin.glsl's tilt
  const double c = 0.5, s = 0.8660254;
  return {q.x, c * q.y - s * q.z, s * q.y + c * q.z};
}

// C++ twins of the exact maps in scenes/hard/ (keep in step with the .glsl).
double grazing_map(const dvec3& p) { return p.y; }
double silhouette_map(const dvec3& p) { return glm::length(p) - 1.0; }
double thin_map_gap(const dvec3& p, double gap) {
  const double plate = sd_box(rot_x60(p - dvec3(-1.6, -0.7, 0.0)), dvec3(0.8, 0.0005, 0.6));
  const double torus = sd_torus(rot_x60(p - dvec3(1.6, -0.7, 0.0)), 0.7, 0.02);
  const double h = 0.5 * gap + 0.6;
  const double walls = std::min(sd_box(p - dvec3(-h, 1.0, 0.0), dvec3(0.6, 0.5, 1.0)),
                                sd_box(p - dvec3(h, 1.0, 0.0), dvec3(0.6, 0.5, 1.0)));
  return std::min(plate, std::min(torus, walls));
}
double thin_map(const dvec3& p) { return thin_map_gap(p, 0.08); }
double far_map(const dvec3& p) {
  return std::min({glm::length(p - dvec3(-0.45, 0, 1) * 1e3) - 100.0, glm::length(p - dvec3(0, 0, 1) * 1e4) - 1e3,
                   glm::length(p - dvec3(0.45, 0, 1) * 1e5) - 1e4});
}
double offset_map(const dvec3& w) {
  const dvec3 p = w - dvec3(1e5, 0, 0);
  return std::min(glm::length(p - dvec3(0, 1, 0)) - 1.0, sd_box(p - dvec3(0, -0.25, 0), dvec3(2, 0.25, 2)));
}
double camera_map(const dvec3& p) { return std::min(p.y, sd_box(p - dvec3(0, 1, 6), dvec3(2, 1, 2))); }
double normals_map(const dvec3& p) {
  const double l = std::min(sd_box(p - dvec3(1.5, 0.15, 0), dvec3(0.8, 0.15, 0.8)),
                            sd_box(p - dvec3(1.5, 0.8, 0.65), dvec3(0.8, 0.8, 0.15)));
  return std::min({p.y, sd_box(p - dvec3(-1.3, 0.6, 0), dvec3(0.6)), l});
}
double acne_map(const dvec3& p) { return std::min(p.y, sd_box(p - dvec3(3, 0, 8), dvec3(2.5, 0.05, 6))); }
double degenerate_map(const dvec3& p) {
  return std::min({p.y + 1.0, glm::length(p - dvec3(-2, 0, 0)), glm::length(p - dvec3(-1, 0, 0)) + 0.5,
                   sd_torus(p, 0.4, 0.0), glm::length(p - dvec3(1, 0, 0)) - 0.3,
                   sd_box(p - dvec3(2, 0, 0), dvec3(0.3, 0.0, 0.3))});
}

struct ExactCase {
  const char* name;
  double (*map)(const dvec3&);
  double slack_rel;  // depth slack: slack_rel * (1 + t) on top of the tolerance (float32 rounding)
  double slack_abs;
  double ambiguity = 1.5;  // tolerances within which a missing ray may stop (float rounding of p adds to it)
};

// Every exact-field case: no NaN/Inf, hit/miss against the exact reference,
// depth within the hit tolerance, steps and step cap within bounds.
class Exact : public ::testing::TestWithParam<ExactCase> {};

const ExactCase kExactCases[] = {
    {"grazing", grazing_map, 1e-5, 0},      {"silhouette", silhouette_map, 1e-5, 0},
    {"thin", thin_map, 1e-5, 0},            {"far", far_map, 1e-5, 0},
    {"offset", offset_map, 1e-5, 0.05, 10.0},     {"normals", normals_map, 1e-5, 0},
    {"acne", acne_map, 1e-5, 0},            {"degenerate", degenerate_map, 1e-5, 0},
    {"on_surface", camera_map, 1e-5, 0},
};
INSTANTIATE_TEST_SUITE_P(Hard, Exact, ::testing::ValuesIn(kExactCases),
                         [](const ::testing::TestParamInfo<ExactCase>& i) { return std::string(i.param.name); });

TEST_P(Exact, HitsDepthsAndStepsHold) {
  const ExactCase& k = GetParam();
  TempDir dir;
  const Scene s = load_scene(hard_scene(k.name));
  const Aovs a = render_aovs(dir, hard_scene(k.name), "a.exr");
  ASSERT_EQ(a.w(), kW);
  EXPECT_EQ(a.nonfinite(), 0);
  const HitCheck c = check_hits(a, s, k.map, [&](double t) { return k.slack_rel * (1.0 + t) + k.slack_abs; }, k.ambiguity);
  const double steps = a.mean("steps"), cap = a.fraction_over_half("step_cap");
  std::printf("%s: ref hits %d ambiguous %d false miss %d false hit %d (%.5f); silhouette hits %d; depth bad %d of "
              "%d worst %.3f; steps %.3f cap %.5f\n",
              k.name, c.ref_hits, c.ambiguous, c.false_miss, c.false_hit, c.misclassified(), c.silhouette_hits,
              c.depth_bad,
              c.depth_checked, c.worst_depth_ratio, steps, cap);
  const std::string t = k.name;
  EXPECT_LE(c.misclassified(), bound(t, "misclassified"));
  EXPECT_LE(static_cast<double>(c.depth_bad) / std::max(c.depth_checked, 1), bound(t, "depth_bad"));
  EXPECT_LE(steps, bound(t, "mean_primary_steps"));
  EXPECT_LE(cap, bound(t, "step_cap_fraction"));
  RecordProperty("misclassified_ppm", static_cast<int>(1e6 * c.misclassified()));
  RecordProperty("depth_bad", c.depth_bad);
}


// ---- 5. Camera inside a solid / exactly on a surface: the whole view is
// that surface at t = 0 (documented limit), in one step, with finite colour.
TEST(HardCamera, InsideASolidOrOnASurfaceSeesItAtDepthZero) {
  TempDir dir;
  for (const char* name : {"inside", "on_surface"}) {
    const Aovs a = render_aovs(dir, hard_scene(name), std::string(name) + ".exr");
    ASSERT_EQ(a.w(), kW) << name;
    EXPECT_EQ(a.nonfinite(), 0) << name;
    EXPECT_EQ(a.fraction_over_half("hit"), 1.0) << name;
    EXPECT_EQ(a.mean("steps"), 1.0) << name;
    EXPECT_EQ(a.mean("Z"), 0.0) << name;
  }
}

// ---- 6. Non-Lipschitz fields: with the declared factor the hit/miss image
// matches a converged reference (reference preset, twice the factor); with
// lipschitz = 1 the tracer overshoots and it does not (the test's power).
struct DeformCase {
  const char* name;
  const char* lipschitz;   // as written in the .toml
  const char* reference;   // twice that
};
class Deform : public ::testing::TestWithParam<DeformCase> {};
INSTANTIATE_TEST_SUITE_P(Hard, Deform,
                         ::testing::Values(DeformCase{"twist", "3.0", "6.0"}, DeformCase{"bend", "2.0", "4.0"},
                                           DeformCase{"displace", "3.0", "6.0"}, DeformCase{"squash", "4.0", "8.0"}),
                         [](const ::testing::TestParamInfo<DeformCase>& i) { return std::string(i.param.name); });

// Fraction of pixels where `a` and the reference `b` disagree on hit or
// miss, or both hit and their depths differ by more than a pixel footprint
// (`pixel_angle` * t): an overshoot inside the surface.
double disagreement(const Aovs& a, const Aovs& b, double pixel_angle) {
  int n = 0;
  for (int y = 0; y < a.h(); ++y)
    for (int x = 0; x < a.w(); ++x) {
      const double za = a.at(x, y, "Z"), zb = b.at(x, y, "Z");
      n += a.hit(x, y) != b.hit(x, y) || (a.hit(x, y) && std::abs(za - zb) > pixel_angle * zb);
    }
  return static_cast<double>(n) / (static_cast<double>(a.w()) * a.h());
}

TEST_P(Deform, DeclaredLipschitzMatchesTheConvergedReference) {
  const DeformCase& k = GetParam();
  const std::string lip = std::string("lipschitz = ") + k.lipschitz;
  TempDir dir;
  const Aovs shipped = render_aovs(dir, hard_scene(k.name), "s.exr");
  const Aovs ref = render_aovs(dir, hard_variant(dir, k.name, "ref", {{lip, std::string("lipschitz = ") + k.reference +
                                                                               "\nmax_steps = 4000"}}),
                               "r.exr", {"--preset", "reference"});
  const Aovs naive = render_aovs(dir, hard_variant(dir, k.name, "naive", {{lip, "lipschitz = 1.0"}}), "n.exr");
  ASSERT_EQ(shipped.w(), kW);
  ASSERT_EQ(ref.w(), kW);
  ASSERT_EQ(naive.w(), kW);
  EXPECT_EQ(shipped.nonfinite() + ref.nonfinite() + naive.nonfinite(), 0);
  const Scene s = load_scene(hard_scene(k.name));
  const double pixel_angle = 2.0 * std::tan(glm::radians(s.camera.fov_deg) / 2.0) / kH;
  const double d = disagreement(shipped, ref, pixel_angle), dn = disagreement(naive, ref, pixel_angle);
  const double steps = shipped.mean("steps"), cap = shipped.fraction_over_half("step_cap");
  std::printf("%s: declared %.5f naive %.5f steps %.3f cap %.5f\n", k.name, d, dn, steps, cap);
  const std::string t = k.name;
  EXPECT_LE(d, bound(t, "misclassified"));
  EXPECT_LE(steps, bound(t, "mean_primary_steps"));
  EXPECT_LE(cap, bound(t, "step_cap_fraction"));
  EXPECT_GE(dn, bound(t, "naive_misclassified_min")) << "lipschitz = 1 should visibly overshoot";
}

// ---- 7. Self-intersection: a flat ground lit by a sun 3 degrees up has no
// occluder, so its shadow AOV must be 1 with (almost) no variance: acne would
// show as dark speckles. The mirror slab's grazing reflections must leave it
// (a self-hit stops in one step).
TEST(HardSelfIntersection, NoShadowAcneNoSelfReflection) {
  TempDir dir;
  const Aovs a = render_aovs(dir, hard_scene("acne"), "a.exr");
  ASSERT_EQ(a.w(), kW);
  double sum = 0, sum2 = 0, lo = 1;
  int n = 0, mirror = 0, self_hits = 0;
  for (int y = 0; y < a.h(); ++y)
    for (int x = 0; x < a.w(); ++x) {
      if (!a.hit(x, y)) continue;
      if (a.at(x, y, "material") < 0.5f) {
        const double v = a.at(x, y, "shadow");
        sum += v;
        sum2 += v * v;
        lo = std::min(lo, v);
        ++n;
      } else {
        ++mirror;
        self_hits += a.at(x, y, "reflection_steps") <= 1.0f;
      }
    }
  ASSERT_GT(n, kW * kH / 4);
  ASSERT_GT(mirror, 100);
  const double mean = sum / n, var = sum2 / n - mean * mean;
  std::printf("acne: ground %d mean %.6f var %.3g min %.4f; mirror %d self hits %d\n", n, mean, var, lo, mirror,
              self_hits);
  EXPECT_LE(var, bound("acne", "shadow_variance"));
  EXPECT_GE(lo, bound("acne", "shadow_min"));
  EXPECT_LE(self_hits, bound("acne", "mirror_self_hits"));
}

// ---- 8. Normals: unit length, and within 5 degrees of the exact normal
// except where an edge lies within a pixel footprint of the hit (the
// gradient there is a blend by design); the ground out to t = 1e3 included.
TEST(HardNormals, MatchTheExactNormalAwayFromEdges) {
  TempDir dir;
  const Scene s = load_scene(hard_scene("normals"));
  const Aovs a = render_aovs(dir, hard_scene("normals"), "n.exr");
  ASSERT_EQ(a.w(), kW);
  int checked = 0, off = 0, far = 0, edges = 0;
  double worst = 0;
  for (int y = 0; y < a.h(); ++y)
    for (int x = 0; x < a.w(); ++x) {
      if (!a.hit(x, y)) continue;
      const glm::dvec3 n(a.at(x, y, "N.x"), a.at(x, y, "N.y"), a.at(x, y, "N.z"));
      EXPECT_NEAR(glm::length(n), 1.0, 1e-4) << x << "," << y;
      const CpuRay ray = cpu_camera_ray(s.camera, kW, kH, x, y);
      const RefHit ref = ref_trace(ray, normals_map, s.quality);
      if (!ref.hit) continue;
      const glm::dvec3 d = glm::normalize(glm::dvec3(ray.d)), p = glm::dvec3(ray.o) + ref.t * d;
      // An edge within a footprint: the exact normal changes across it.
      const double fp = ref.t * ray.spread;
      bool edge = false;
      for (const glm::dvec3 o : {glm::dvec3(fp, 0, 0), glm::dvec3(0, fp, 0), glm::dvec3(0, 0, fp)})
        for (const double sgn : {-1.0, 1.0}) {
          const glm::dvec3 q = p + sgn * o;
          edge = edge || glm::dot(ref_normal(normals_map, q - ref.n * normals_map(q), 1.0), ref.n) < 0.999;
        }
      if (edge) {
        ++edges;
        continue;
      }
      const double angle = std::acos(std::clamp(glm::dot(n, ref.n), -1.0, 1.0)) * 180.0 / 3.14159265358979;
      ++checked;
      far += ref.t > 100.0;
      off += angle > 5.0;
      worst = std::max(worst, angle);
    }
  std::printf("normals: checked %d (far %d) edges %d off %d worst %.3f deg\n", checked, far, edges, off, worst);
  EXPECT_GT(checked, kW * kH / 2);
  EXPECT_GT(far, 50) << "the test must see the ground far away";
  EXPECT_LE(static_cast<double>(off) / checked, bound("normals", "normal_off_5deg"));
}

// ---- 3. Thin features keep their topology: along the scanline through the
// hairline gap every pixel the reference sees through the gap is a miss, and
// along the scanlines through the plate and the torus the GPU has as many
// hit runs as the reference.
int runs(const std::vector<bool>& row) {
  int r = 0;
  for (size_t i = 0; i < row.size(); ++i) r += row[i] && (i == 0 || !row[i - 1]);
  return r;
}
TEST(HardThin, GapStaysOpenPlateAndTorusKeepTheirRuns) {
  TempDir dir;
  const Scene s = load_scene(hard_scene("thin"));
  const Aovs a = render_aovs(dir, hard_scene("thin"), "t.exr");
  ASSERT_EQ(a.w(), kW);
  int gap_pixels = 0, rows_checked = 0, run_mismatch = 0;
  for (int y = 0; y < kH; ++y) {
    std::vector<bool> gpu(kW), ref(kW);
    for (int x = 0; x < kW; ++x) {
      const CpuRay ray = cpu_camera_ray(s.camera, kW, kH, x, y);
      const RefHit r = ref_trace(ray, thin_map, s.quality);
      gpu[x] = a.hit(x, y);
      ref[x] = r.hit;
      // Through the gap: the ray passes between the walls (|x| < gap/2 at z = -1).
      const glm::dvec3 d = glm::normalize(glm::dvec3(ray.d));
      const double tz = (-1.0 - ray.o.z) / d.z;
      const glm::dvec3 q = glm::dvec3(ray.o) + tz * d;
      if (!r.hit && std::abs(q.x) < 0.04 && q.y > 0.5 && q.y < 1.5) {
        ++gap_pixels;
        EXPECT_FALSE(a.hit(x, y)) << "the gap closed at " << x << "," << y;
      }
    }
    const int rg = runs(gpu), rr = runs(ref);
    rows_checked += rr > 0;
    run_mismatch += rg != rr;
  }
  std::printf("thin: gap pixels %d, rows with hits %d, run mismatches %d\n", gap_pixels, rows_checked, run_mismatch);
  EXPECT_GE(gap_pixels, 10) << "the gap must be seen through by whole pixels";
  EXPECT_LE(run_mismatch, bound("thin", "row_run_mismatches"));
}

// The gap with a tolerance as wide as the fast preset's (0.5 footprint)
// closes: the topology check above has the power to fail.
TEST(HardThin, AWideToleranceClosesTheGap) {
  TempDir dir;
  const fs::path p = hard_variant(dir, "thin", "wide", {{"[render]", "[quality]\nhit_tolerance = 3.0\n\n[render]"}});
  const Aovs a = render_aovs(dir, p, "w.exr");
  ASSERT_EQ(a.w(), kW);
  const Scene s = load_scene(hard_scene("thin"));
  int closed = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const CpuRay ray = cpu_camera_ray(s.camera, kW, kH, x, y);
      const glm::dvec3 d = glm::normalize(glm::dvec3(ray.d));
      const glm::dvec3 q = glm::dvec3(ray.o) + ((-1.0 - ray.o.z) / d.z) * d;
      closed += std::abs(q.x) < 0.04 && q.y > 0.5 && q.y < 1.5 && !ref_trace(ray, thin_map, s.quality).hit &&
                a.hit(x, y);
    }
  EXPECT_GT(closed, 0);
}

// ---- 10. Two parallel mirrors, 16 bounces: finite, bounded radiance; the
// throughput cut-off ends paths early (F0 0.2: 0.2^5 < 1e-3 at normal
// incidence; Fresnel raises F towards 1 at grazing angles, so a few paths go
// on: bounces 11..16 must cost far less per bounce than bounces 3..10).
TEST(HardMirrors, DeepChainsStayFiniteAndAreCutOff) {
  TempDir dir;
  const Aovs deep = render_aovs(dir, hard_scene("mirrors"), "m.exr");
  ASSERT_EQ(deep.w(), kW);
  EXPECT_EQ(deep.nonfinite(), 0);
  double max_c = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (const char* c : {"R", "G", "B"}) max_c = std::max<double>(max_c, deep.at(x, y, c));
  EXPECT_LE(max_c, bound("mirrors", "max_colour"));
  auto half = [&](const char* bounces) {
    return render_aovs(dir, hard_variant(dir, "mirrors", "h", {{"reflectivity = 0.9", "reflectivity = 0.2"},
                                                               {"bounces = 16", std::string("bounces = ") + bounces}}),
                       std::string("h") + bounces + ".exr")
        .mean("sdf_evals");  // each shaded bounce adds its AO taps and shadow steps
  };
  const double b16 = half("16"), b10 = half("10"), b2 = half("2");
  std::printf("mirrors: max colour %.4f; F0 0.2 sdf evals: 16 bounces %.3f, 10 %.3f, 2 %.3f\n", max_c, b16, b10, b2);
  // Per extra bounce, bounces 11..16 cost a small fraction of bounces 3..10:
  // most paths were cut off; only near-grazing ones (F -> 1) go on.
  EXPECT_GT(b10, b2) << "the test would lose its power";
  const double late = (b16 - b10) / 6.0, early = (b10 - b2) / 8.0;
  EXPECT_LE(late / early, bound("mirrors", "late_bounce_cost_ratio"));
}

// ---- 9. Degenerate input that cannot be rendered is rejected at load with
// file:line and the key, one line, exit 2, nothing written.
TEST(HardDegenerate, InvalidValuesAreRejectedAtLoad) {
  TempDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"up_parallel", ":8: 'camera.up' is parallel"},       {"zero_direction", ":7: 'lights[0].direction'"},
      {"nan_value", ":6: 'lights[0].position[1]' must be a finite"}, {"inf_uniform", ":7: 'materials[0].color[1]'"},
      {"zero_radius", ":7: 'bounds.radius' must be > 0"},   {"negative_size", ":6: 'lights[0].size' must be >= 0"},
  };
  for (const auto& [name, want] : cases) {
    const fs::path p = source_dir() / "tests/data/stability" / (std::string(name) + ".toml");
    const RunResult r = run_marchstudio({"render", p.string(), "-o", (dir / "x.png").string()});
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_NE(r.err.find(std::string(name) + ".toml" + want), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // A NaN through -D into a scene define is a shader error (bad input), not a render.
  const RunResult r = run_marchstudio({"render", hard_scene("thin").string(), "-o", (dir / "x.png").string(), "-D",
                                       "THIN_GAP=nan", "--size", "16x9"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace ms::test
