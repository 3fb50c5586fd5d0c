// The tracer of sdf_shaders/trace.glsl through the real binary:
// over-relaxation against plain sphere tracing (hit or miss, steps); the
// default tracer's primary steps and depths against a CPU twin (analytic
// plane, bounding sphere, over-relaxation) on the seed scene; and every
// shipped scene's [bounds] holding its map().
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "cpu_tracer.h"
#include "io/image_io.h"
#include "run.h"
#include "scene/load.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string scene(const std::string& name) { return (source_dir() / "scenes" / (name + ".toml")).string(); }

// A scene file's text with more [quality] keys (lines "key = value\n"):
// added to its [quality] table, or in a new one.
std::string with_quality(std::string text, const std::string& keys) {
  const size_t at = text.find("\n[quality]\n");
  if (at == std::string::npos) return text + "\n[quality]\n" + keys;
  return text.insert(at + 11, keys);
}

// A shipped scene with extra [quality] keys, written next to a copy of its map.
fs::path scene_variant(const TempDir& dir, const std::string& scene_name, const std::string& name,
                       const std::string& quality) {
  const Scene s = load_scene(scene(scene_name));
  write_file(dir / s.map_file.filename().string(), read_file(s.map_file));
  const fs::path p = dir / (name + ".toml");
  write_file(p, with_quality(read_file(scene(scene_name)), quality));
  return p;
}
fs::path seed_variant(const TempDir& dir, const std::string& name, const std::string& quality) {
  return scene_variant(dir, "seed", name, quality);
}

// Fraction of pixels whose hit/miss differs between two renders' `hit` AOV.
double hit_disagreement(const Image& a, const Image& b) {
  const auto ch = [](const Image& img) {
    return static_cast<int>(std::find(img.channels.begin(), img.channels.end(), "hit") - img.channels.begin());
  };
  const int ca = ch(a), cb = ch(b);
  size_t differ = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) differ += (a.at(x, y, ca) > 0.5f) != (b.at(x, y, cb) > 0.5f);
  return static_cast<double>(differ) / (static_cast<double>(a.width) * a.height);
}

Image render_hits(const TempDir& dir, const fs::path& toml, const std::string& out) {
  const RunResult r = run_marchstudio(
      {"render", toml.string(), "--size", "640x360", "--aov", "hit,steps", "-o", (dir / out).string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_image(dir / out);
}

// Over-relaxation must not change what a ray hits: at most 0.05% of the
// seed's pixels may flip between hit and miss against plain sphere tracing
// at the same tolerance. Checked on the whole field marched (the textbook
// geometry: grazing rays along the plane are where relaxation works hardest)
// and with the default tracer.
TEST(OverRelaxation, ChangesHitOrMissOfAtMostOneInTwoThousandPixels) {
  TempDir dir;
  for (const std::string geometry : {"preset = \"textbook\"\nhit_tolerance = 0.5\n", "preset = \"balanced\"\n"}) {
    const Image plain = render_hits(dir, seed_variant(dir, "plain", geometry + "omega = 1.0\n"), "plain.exr");
    for (const char* omega : {"1.2", "1.5", "1.8"}) {
      const Image relaxed =
          render_hits(dir, seed_variant(dir, "relaxed", geometry + "omega = " + omega + "\n"), "relaxed.exr");
      const double f = hit_disagreement(plain, relaxed);
      RecordProperty(std::string("flips_ppm_omega_") + omega, static_cast<int>(1e6 * f));
      EXPECT_LE(f, 0.0005) << geometry << "omega " << omega;
    }
  }
}

// The over-relaxed march must actually save steps where rays graze (the
// textbook geometry), or it is not worth its code.
TEST(OverRelaxation, SavesStepsOnGrazingRays) {
  TempDir dir;
  const std::string g = "preset = \"textbook\"\nhit_tolerance = 0.5\n";
  auto steps = [&](const char* omega) {
    const RunResult r = run_marchstudio({"bench", seed_variant(dir, "s", g + "omega = " + omega + "\n").string(),
                                         "--size", "160x90", "--frames", "1", "--warmup", "0", "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out).at("cost").at("primary_steps").at("mean").get<double>();
  };
  EXPECT_LT(steps("1.5"), 0.9 * steps("1.0"));
}

// ---- A CPU twin of trace.glsl's default path on the seed: the plane y = 0
// intersected exactly, the sphere marched inside its bounding sphere, over-
// relaxed with overshoot fallback. float32 like the GPU.
struct TwinHit {
  int steps = 0;
  bool hit = false, exact = false;
  float t = 0;
};

TwinHit twin_trace(const CpuRay& r, const Quality& q, const Scene& s) {
  TwinHit out;
  const glm::vec3 pn = s.planes.at(0).normal;
  const float pw = s.planes.at(0).offset;
  float tPlane = q.max_distance;
  const float dn = glm::dot(r.d, pn), h0 = glm::dot(r.o, pn) + pw;
  const float tp = h0 <= 0.0f ? 0.0f : (dn < 0.0f ? -h0 / dn : 1e20f);
  const bool plane = tp <= tPlane;
  if (plane) tPlane = tp;
  const glm::vec3 c = s.bounds.center, oc = r.o - c;
  const float b = glm::dot(oc, r.d), disc = b * b - (glm::dot(oc, oc) - s.bounds.radius * s.bounds.radius);
  float t = 0.0f, tEnd = tPlane;
  if (disc < 0.0f) {
    t = 1e20f;
    tEnd = std::min(tEnd, -1e20f);
  } else {
    t = std::max(t, -b - std::sqrt(disc));
    tEnd = std::min(tEnd, -b + std::sqrt(disc));
  }
  if (t <= tEnd) {
    float omega = q.omega, tPrev = t, rPrev = 0.0f, stepLen = 0.0f;
    for (int i = 0; i < q.max_steps; ++i) {
      const float h = glm::length(r.o + r.d * t - glm::vec3(0.0f, 1.0f, 0.0f)) - 1.0f;
      out.steps = i + 1;
      const float rad = h / q.lipschitz;
      if (omega > 1.0f && stepLen > 0.0f && (std::abs(rad) + rPrev < stepLen || h < 0.0f)) {
        t = tPrev + rPrev;
        omega = 1.0f;
        continue;
      }
      if (h < std::max(q.hit_epsilon, q.hit_tolerance * t * r.spread)) {
        out.hit = true;
        break;
      }
      stepLen = t + omega * rad > tEnd ? rad : omega * rad;
      tPrev = t;
      rPrev = rad;
      t += stepLen;
      if (t > tEnd) break;
    }
  }
  if (out.hit || !plane) {
    out.t = std::min(t, q.max_distance);
    return out;
  }
  out.hit = out.exact = true;
  out.t = tPlane;
  return out;
}

class DefaultTracer : public ::testing::TestWithParam<std::string> {};

// The seed as shipped, and with stronger over-relaxation.
INSTANTIATE_TEST_SUITE_P(Omega, DefaultTracer, ::testing::Values("", "1.5"),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           return i.param.empty() ? std::string("shipped") : "omega_1_5";
                         });

TEST_P(DefaultTracer, MatchesItsCpuTwinOnTheSeed) {
  constexpr int W = 96, H = 54;
  TempDir dir;
  const fs::path toml = GetParam().empty() ? fs::path(scene("seed")) : seed_variant(dir, "v", "omega = " + GetParam() + "\n");
  const Scene seed = load_scene(toml);
  ASSERT_EQ(seed.planes.size(), 1u);
  ASSERT_EQ(seed.bounds.kind, BoundsKind::sphere);
  const Quality& q = seed.quality;
  const RunResult r = run_marchstudio({"render", toml.string(), "--size", std::to_string(W) + "x" + std::to_string(H),
                                       "--aov", "steps,depth,cost", "-o", (dir / "d.exr").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "d.exr");
  const auto ch = [&](const char* n) {
    return static_cast<int>(std::find(img.channels.begin(), img.channels.end(), n) - img.channels.begin());
  };
  int agree = 0, marched = 0, gpu_marched = 0, depth_ok = 0, exact_hits = 0;
  double gpu_sum = 0, cpu_sum = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const CpuRay ray = cpu_camera_ray(seed.camera, W, H, x, y);
      const TwinHit c = twin_trace(ray, q, seed);
      const float g = img.at(x, y, ch("steps"));
      agree += static_cast<int>(g) == c.steps;
      marched += c.steps > 0;
      gpu_marched += g > 0.0f;
      gpu_sum += g;
      cpu_sum += c.steps;
      EXPECT_EQ(img.at(x, y, ch("hit")) > 0.5f, c.hit) << x << "," << y;
      if (c.hit) depth_ok += std::abs(img.at(x, y, ch("Z")) - c.t) <= 1e-4f * (1.0f + c.t);
      exact_hits += c.exact;
      // A plane pixel is exact: its depth equals the analytic intersection.
      if (c.exact) {
        const ExactHit e = exact_seed_hit(ray, q.max_distance);
        EXPECT_NEAR(img.at(x, y, ch("Z")), e.t, 1e-5 * (1.0 + e.t)) << x << "," << y;
      }
    }
  EXPECT_GE(agree, static_cast<int>(std::ceil(0.99 * W * H))) << agree << " of " << W * H;
  EXPECT_NEAR(gpu_sum, cpu_sum, 0.01 * cpu_sum + 1.0);
  EXPECT_NEAR(gpu_marched, marched, 0.01 * marched + 1);
  EXPECT_GT(marched, W * H / 20) << "the sphere's pixels march: the test would lose its power otherwise";
  EXPECT_LT(marched, W * H / 3) << "only pixels that see the bounding sphere march";
  EXPECT_GT(exact_hits, W * H / 3);
  EXPECT_GE(depth_ok, static_cast<int>(std::ceil(0.99 * (exact_hits + marched / 2))));
  // No ray runs into the step cap with the default tracer.
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) ASSERT_LT(img.at(x, y, ch("step_cap")), 0.5f) << x << "," << y;
}

// Every shipped scene's [bounds] really contains its map(): the default
// tracer and plain marching of the whole field (no bounds, no analytic
// planes) at the same tolerance agree on hit and miss.
TEST(SceneBounds, HoldEverythingTheMapDraws) {
  TempDir dir;
  for (const char* name : {"seed", "stilllife", "columns"}) {
    const std::string size = "320x180";
    auto hits = [&](const std::string& preset, const std::string& out) {
      const RunResult r = run_marchstudio({"render", scene(name), "--preset", preset, "--size", size, "--aov", "hit",
                                           "-o", (dir / out).string()});
      EXPECT_EQ(r.exit_code, 0) << r.err;
      return read_image(dir / out);
    };
    const Image bounded = hits("reference", "b.exr");
    const fs::path variant = scene_variant(dir, name, name, "preset = \"reference\"\nbounds = false\n"
                                                             "analytic_planes = false\nmax_steps = 4000\n");
    const RunResult r = run_marchstudio(
        {"render", variant.string(), "--size", size, "--aov", "hit", "-o", (dir / "m.exr").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image marched = read_image(dir / "m.exr");
    EXPECT_LE(hit_disagreement(bounded, marched), 0.0005) << name;
  }
}

}  // namespace
}  // namespace ms::test
