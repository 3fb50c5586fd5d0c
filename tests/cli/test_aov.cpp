// render --aov through the real binary: the EXR's channels, the error for
// non-EXR outputs, colour unchanged by the AOV build, and the AOV values
// themselves checked against an independent CPU tracer (primary steps) and
// exact ray-sphere / ray-plane intersection (depth) on the seed scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "cpu_tracer.h"
#include "io/image_io.h"
#include "render/aov.h"
#include "run.h"
#include "scene/load.h"
#include "scene/quality.h"

namespace ms::test {
namespace {

std::string seed_toml() { return (source_dir() / "scenes/seed.toml").string(); }

Image render_aov(TempDir& dir, const std::string& name, int w, int h, const std::string& aovs,
                 std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", seed_toml(), "-o", (dir / name).string(), "--size",
                                   std::to_string(w) + "x" + std::to_string(h), "--aov", aovs};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_marchstudio(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(dir / name);
}

// Index of a named channel; fails the test when absent.
int ch(const Image& img, const std::string& name) {
  const auto it = std::find(img.channels.begin(), img.channels.end(), name);
  EXPECT_NE(it, img.channels.end()) << "no channel " << name;
  return it == img.channels.end() ? 0 : static_cast<int>(it - img.channels.begin());
}

TEST(Aov, ExrHasTheDocumentedChannels) {
  TempDir dir;
  const Image all = render_aov(dir, "all.exr", 32, 18, "depth,normal,steps,material,shadow,ao,cost");
  const std::set<std::string> want = {"R",        "G",      "B",  "A",           "hit",
                                      "Z",        "N.x",    "N.y", "N.z",        "steps",
                                      "material", "shadow", "ao", "shadow_steps", "reflection_steps",
                                      "sdf_evals", "step_cap"};
  EXPECT_EQ(std::set<std::string>(all.channels.begin(), all.channels.end()), want);
  EXPECT_EQ(all.channels.size(), want.size());  // no duplicates

  // Only what was asked for, plus `hit` (it tells a miss from a zero).
  const Image depth = render_aov(dir, "depth.exr", 32, 18, "depth,depth");
  EXPECT_EQ(std::set<std::string>(depth.channels.begin(), depth.channels.end()),
            (std::set<std::string>{"R", "G", "B", "A", "hit", "Z"}));
}

TEST(Aov, PngOutputIsAnErrorAndWritesNothing) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", seed_toml(), "-o", (dir / "x.png").string(), "--aov", "depth"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--aov"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Aov, UnknownNameIsAnError) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", seed_toml(), "-o", (dir / "x.exr").string(), "--aov", "depht"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("depht"), std::string::npos) << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Aov, ColourIsTheSameAsWithoutAovs) {
  TempDir dir;
  const Image aov = render_aov(dir, "aov.exr", 64, 36, "cost,normal", {"--spp", "4"});
  const RunResult r = run_marchstudio(
      {"render", seed_toml(), "-o", (dir / "plain.exr").string(), "--size", "64x36", "--spp", "4"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image plain = read_image(dir / "plain.exr");
  ASSERT_EQ(plain.width, aov.width);
  size_t differ = 0;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x)
      for (const char* c : {"R", "G", "B"}) differ += plain.at(x, y, ch(plain, c)) != aov.at(x, y, ch(aov, c));
  EXPECT_EQ(differ, 0u);  // the counters must not perturb the shading, not even by one ulp
}

TEST(Aov, CountersAddUp) {
  // sdf_evals counts every map() call: the primary and reflection steps,
  // the shadow steps, and per shaded hit 4 normal taps + AO_TAPS. So the
  // remainder is a whole number of shaded hits (at most 1 + bounces).
  TempDir dir;
  // The textbook preset: every hit computes its normal (the default tracer
  // gives analytic plane hits their exact normal, without the 4 taps).
  const Scene seed = load_scene(seed_toml());
  const int per_hit = 4 + seed.quality.ao_taps;
  const Image img = render_aov(dir, "cost.exr", 48, 27, "cost,steps", {"--preset", "textbook"});
  int shaded_twice = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int rest = static_cast<int>(img.at(x, y, ch(img, "sdf_evals")) - img.at(x, y, ch(img, "steps")) -
                                        img.at(x, y, ch(img, "shadow_steps")) -
                                        img.at(x, y, ch(img, "reflection_steps")));
      ASSERT_EQ(rest % per_hit, 0) << x << "," << y;
      ASSERT_GE(rest / per_hit, 0);
      ASSERT_LE(rest / per_hit, 1 + seed.quality.bounces);
      shaded_twice += rest / per_hit == 2;
    }
  EXPECT_GT(shaded_twice, 0) << "no pixel shaded a reflection hit: the test lost its power";
}

// Primary step counts against the CPU tracer on a tiny image. Tolerance:
// llvmpipe and the CPU both use float32, but their operation order (and
// llvmpipe's fused multiply-adds) differ in the last bits; where a ray ends
// right at the tolerance that can flip one step or the hit test, so a few
// pixels may differ. >= 99% of pixels must agree exactly, the mean within 1%.
TEST(Aov, PrimaryStepsMatchTheCpuTracer) {
  constexpr int W = 24, H = 14;
  TempDir dir;
  // The CPU tracer is plain sphere tracing of the whole field: the textbook
  // preset (the default tracer has its own CPU twin in test_presets.cpp).
  Scene seed = load_scene(seed_toml());
  seed.quality = with_preset(seed.quality, "textbook");
  const Image img = render_aov(dir, "steps.exr", W, H, "steps,cost", {"--preset", "textbook"});
  ASSERT_EQ(img.width, W);
  int agree = 0, cap_agree = 0;
  double gpu_sum = 0, cpu_sum = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const CpuTrace c = cpu_trace(cpu_camera_ray(seed.camera, W, H, x, y), seed.quality);
      const float g = img.at(x, y, ch(img, "steps"));
      agree += static_cast<int>(g) == c.steps;
      cap_agree += (img.at(x, y, ch(img, "step_cap")) > 0.5f) == c.capped;
      gpu_sum += g;
      cpu_sum += c.steps;
    }
  RecordProperty("pixels_agreeing", agree);
  RecordProperty("gpu_mean_x1000", static_cast<int>(1000 * gpu_sum / (W * H)));
  RecordProperty("cpu_mean_x1000", static_cast<int>(1000 * cpu_sum / (W * H)));
  EXPECT_GE(agree, static_cast<int>(std::ceil(0.99 * W * H))) << agree << " of " << W * H;
  EXPECT_NEAR(gpu_sum, cpu_sum, 0.01 * cpu_sum);
  EXPECT_GE(cap_agree, static_cast<int>(std::ceil(0.99 * W * H)));
  EXPECT_GT(cpu_sum / (W * H), 5.0) << "the CPU tracer took implausibly few steps";
}

// Depth against exact intersection. The tracer stops where the field value
// d < tol(t) (the hit tolerance at t); along a ray meeting the surface at
// angle theta to its normal that is a gap t_exact - t <= tol / cos(theta)
// (exact for the plane, first order for the sphere), and it never
// overshoots (the seed's field is exact). Slack 1e-4 * (1 + t): float32
// positions carry ~1e-7 relative error per operation, a few hundred
// operations along the march give ~1e-5 of t, tenfold margin.
TEST(Aov, DepthMatchesExactIntersection) {
  constexpr int W = 96, H = 54;
  TempDir dir;
  const Scene seed = load_scene(seed_toml());
  const Quality& q = seed.quality;
  const Image img = render_aov(dir, "depth.exr", W, H, "depth,material,cost,normal");
  int checked = 0, rim_hits = 0, horizon_hits = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const CpuRay ray = cpu_camera_ray(seed.camera, W, H, x, y);
      const ExactHit e = exact_seed_hit(ray, q.max_distance);
      const bool hit = img.at(x, y, ch(img, "hit")) > 0.5f;
      const double t = img.at(x, y, ch(img, "Z"));
      const int mat = static_cast<int>(img.at(x, y, ch(img, "material")) + 0.5f);
      const double slack = 1e-4 * (1.0 + t);
      const std::string where = "pixel " + std::to_string(x) + "," + std::to_string(y);
      if (!hit) {
        // Sphere tracing an exact field cannot miss a surface before MAX_DIST.
        EXPECT_FALSE(e.hit && e.t < q.max_distance - slack) << where << " missed a surface at " << e.t;
        EXPECT_EQ(t, 0.0) << where << ": a miss writes depth 0";
        continue;
      }
      ASSERT_LT(img.at(x, y, ch(img, "step_cap")), 0.5f) << where << " capped: this test assumes none";
      EXPECT_LE(t, (e.hit ? e.t : q.max_distance) + slack) << where << " overshot";
      if (e.hit && e.mat == mat) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(ray.d));
        const double cos_theta = std::max(std::abs(glm::dot(d, e.n)), 1e-3);
        EXPECT_LE(e.t - t, cpu_tolerance(ray, q, t) / cos_theta + slack)
            << where << " t " << t << " exact " << e.t << " cos " << cos_theta;
        ++checked;
      } else {
        // A tolerance hit: the ray passes within the tolerance of a surface
        // it does not cross there (silhouettes, the far horizon). The point
        // it stopped at must still lie within the tolerance of that surface.
        const glm::dvec3 p = glm::dvec3(ray.o) + t * glm::normalize(glm::dvec3(ray.d));
        EXPECT_LE(exact_distance_to(mat, p), cpu_tolerance(ray, q, t) + slack) << where;
        ++(mat == 1 ? rim_hits : horizon_hits);
      }
    }
  EXPECT_GT(checked, W * H / 2) << "too few pixels compared";
  // Hit/miss (and object) disagreements are tolerance hits only, and a ray
  // must pass within about half a pixel footprint of a surface to make one:
  // a rim at most one pixel wide around the sphere's silhouette (its
  // projected circumference), and at most one row along the horizon, where
  // the plane lies just beyond MAX_DIST.
  const float dist = glm::length(seed.camera.position - glm::vec3(0.0f, 1.0f, 0.0f));
  const float radius_px = std::tan(std::asin(1.0f / dist)) / std::tan(glm::radians(seed.camera.fov_deg) / 2) * H / 2;
  EXPECT_LE(rim_hits, 2.0f * 3.14159265f * radius_px) << "radius " << radius_px << " px";
  EXPECT_LE(horizon_hits, W);
}

TEST(Aov, MissesAreZeroAndHitsAreUnitNormals) {
  TempDir dir;
  const Image img = render_aov(dir, "n.exr", 48, 27, "normal,material,shadow,ao,depth");
  int misses = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const glm::vec3 n(img.at(x, y, ch(img, "N.x")), img.at(x, y, ch(img, "N.y")), img.at(x, y, ch(img, "N.z")));
      if (img.at(x, y, ch(img, "hit")) < 0.5f) {
        ++misses;
        EXPECT_EQ(glm::length(n), 0.0f);
        EXPECT_EQ(img.at(x, y, ch(img, "shadow")), 0.0f);
        EXPECT_EQ(img.at(x, y, ch(img, "ao")), 0.0f);
        continue;
      }
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f) << x << "," << y;
      const float s = img.at(x, y, ch(img, "shadow")), a = img.at(x, y, ch(img, "ao"));
      EXPECT_TRUE(s >= 0.0f && s <= 1.0f && a >= 0.0f && a <= 1.0f) << x << "," << y;
    }
  EXPECT_GT(misses, 0) << "the seed shows sky at the top";
  // The top row is sky, the bottom row is floor (material 0) lit from above.
  EXPECT_LT(img.at(img.width / 2, 0, ch(img, "hit")), 0.5f);
  const int bottom = img.height - 1;
  EXPECT_EQ(img.at(img.width / 2, bottom, ch(img, "material")), 0.0f);
  EXPECT_GT(img.at(img.width / 2, bottom, ch(img, "N.y")), 0.99f);
}

// DEBUG_VIEW n (through render -D) writes its visualisation as the colour;
// with --aov in the same render, each view is checked against the AOV it
// shows. The EXR is linear with exposure 1 and no tone map, so the colours
// are exactly what the shader wrote.
TEST(Aov, DebugViewsShowTheirAov) {
  TempDir dir;
  std::vector<Image> views(7);
  for (int v = 1; v <= 6; ++v)
    views[v] = render_aov(dir, "v" + std::to_string(v) + ".exr", 48, 27, "steps,normal,depth,ao,shadow,material",
                          {"-D", "DEBUG_VIEW=" + std::to_string(v)});
  auto rgb = [](const Image& img, int x, int y) {
    return glm::vec3(img.at(x, y, ch(img, "R")), img.at(x, y, ch(img, "G")), img.at(x, y, ch(img, "B")));
  };
  std::map<int, glm::vec3> material_colour;
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x) {
      const Image& a = views[1];  // every render has the same AOVs
      const bool hit = a.at(x, y, ch(a, "hit")) > 0.5f;
      const std::string at = std::to_string(x) + "," + std::to_string(y);
      // 1: the heat map, as its C++ mirror (the viewer's legend) computes it.
      const glm::vec3 heat = heat_ramp(steps_heat_position(a.at(x, y, ch(a, "steps"))));
      EXPECT_LT(glm::length(rgb(views[1], x, y) - heat), 1e-5f) << at;
      // 2: normals as 0.5 n + 0.5, black for misses.
      const glm::vec3 n(a.at(x, y, ch(a, "N.x")), a.at(x, y, ch(a, "N.y")), a.at(x, y, ch(a, "N.z")));
      EXPECT_LT(glm::length(rgb(views[2], x, y) - (hit ? 0.5f * n + 0.5f : glm::vec3(0.0f))), 1e-5f) << at;
      // 3: depth, grey on a log scale.
      const float t = a.at(x, y, ch(a, "Z"));
      const float grey = hit ? 1.0f - std::log2(1.0f + t) / std::log2(101.0f) : 0.0f;
      EXPECT_NEAR(views[3].at(x, y, 0), grey, 1e-5f) << at;
      // 4, 5: AO and shadow as grey.
      EXPECT_EQ(views[4].at(x, y, 1), a.at(x, y, ch(a, "ao"))) << at;
      EXPECT_EQ(views[5].at(x, y, 1), a.at(x, y, ch(a, "shadow"))) << at;
      // 6: one colour per material id, black for misses.
      if (!hit) {
        EXPECT_EQ(glm::length(rgb(views[6], x, y)), 0.0f) << at;
        continue;
      }
      const int id = static_cast<int>(a.at(x, y, ch(a, "material")));
      const auto [it, fresh] = material_colour.emplace(id, rgb(views[6], x, y));
      EXPECT_EQ(it->second, rgb(views[6], x, y)) << at;
    }
  ASSERT_EQ(material_colour.size(), 2u);
  EXPECT_GT(glm::length(material_colour[0] - material_colour[1]), 0.2f);
  // A scene's DEBUG_VIEW out of range is a shader error, reported as bad input.
  const RunResult r = run_marchstudio({"render", seed_toml(), "-o", (dir / "bad.exr").string(), "--size", "8x8",
                                       "-D", "DEBUG_VIEW=9"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("DEBUG_VIEW"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
