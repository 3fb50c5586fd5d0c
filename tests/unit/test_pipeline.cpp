// The frame pipeline's pieces that need no GL (pipeline/): prepare() turns
// a job into assembled passes and frame settings, the NaN/Inf guard says
// one thing everywhere, and every written frame carries one set of tags.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "core/version.h"
#include "files.h"
#include "pipeline/fingerprint.h"
#include "pipeline/nonfinite.h"
#include "pipeline/prepare.h"
#include "pipeline/shader_dir.h"

namespace ms::test {
namespace {

FrameJob seed_job() {
  FrameJob job;
  job.input = source_dir() / "scenes/seed.toml";
  job.output = "seed.png";
  job.shader_dir = resolve_shader_dir({});
  return job;
}

bool has_define(const AssembleOptions& o, const std::string& name) {
  return std::any_of(o.defines.begin(), o.defines.end(), [&](const auto& d) { return d.first == name; });
}

TEST(Prepare, AssemblesTheScenesPassAndSettingsWithoutAContext) {
  FrameJob job = seed_job();
  job.size = {64, 36};
  const PreparedFrame p = prepare(job, true);
  ASSERT_EQ(p.in.passes.size(), 1u);
  EXPECT_FALSE(p.in.shadertoy);
  EXPECT_EQ(p.fp.width, 64);
  EXPECT_EQ(p.fp.height, 36);
  EXPECT_EQ(p.fp.spp, 1);              // the scene's
  EXPECT_TRUE(p.fp.fused_post);        // one sample, no AOVs, no bloom: the pass writes the image
  EXPECT_FALSE(p.post_src.text.empty());
  EXPECT_NE(p.in.passes[0].source.text.find("map("), std::string::npos);
}

TEST(Prepare, AovsAndSamplesKeepThePostPassAndAddTheOutputs) {
  FrameJob job = seed_job();
  job.spp = 4;
  job.aov_channels = {"depth"};
  const PreparedFrame p = prepare(job, false);
  EXPECT_EQ(p.fp.spp, 4);
  EXPECT_TRUE(p.fp.aovs);
  EXPECT_FALSE(p.fp.fused_post);
  EXPECT_TRUE(has_define(p.opts, "AOV_OUTPUTS"));
  EXPECT_TRUE(has_define(job.assemble_options(), "AOV_OUTPUTS"));
}

TEST(Prepare, AShadertoyInputRefusesAovsBeforeAnyContext) {
  FrameJob job = seed_job();
  job.input = source_dir() / "tests/data/stability/nan_shadertoy.glsl";
  job.aov_channels = {"depth"};
  try {
    prepare(job, false);
    FAIL() << "prepared";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().code, Exit::bad_input);
    EXPECT_EQ(e.info().key, "--aov");
  }
}

TEST(NonfiniteGuard, StrictThrowsOneLineNamingTheFrameAndTheConsequence) {
  try {
    guard_nonfinite({"a.toml", true, "frame 3", "it is not written"}, 5, 100);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().code, Exit::threshold);
    EXPECT_EQ(e.info().key, "--strict");
    EXPECT_EQ(e.info().file, "a.toml");
    EXPECT_EQ(e.info().what, "frame 3: 5 of 100 pixels have NaN/Inf values; it is not written");
  }
  EXPECT_NO_THROW(guard_nonfinite({"a.toml", true, {}, "nothing written"}, 0, 100));
}

TEST(NonfiniteGuard, CountsAPixelOnceWhateverItsChannels) {
  Image a;
  a.width = 2;
  a.height = 1;
  a.channels = {"R", "G"};
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  a.pixels = {1.0f, nan, 0.0f, 0.0f};  // pixel 0 has one bad channel
  Image b = a;
  b.pixels = {inf, inf, 0.0f, inf};    // pixel 0 again, and pixel 1
  EXPECT_EQ(count_nonfinite_pixels(a), 1);
  EXPECT_EQ(count_nonfinite_pixels(a, &b), 2);
}

TEST(FrameMetadata, EveryFrameCarriesTheVersionItsDescriptionAndItsFingerprint) {
  const ImageMetadata still = frame_metadata("dir/seed.toml", 1.5f, 4, "abc");
  EXPECT_EQ(still.at("Software"), kSoftware);
  EXPECT_EQ(still.at("ImageDescription"), "seed.toml t=1.500000 spp=4 fingerprint=abc");
  const ImageMetadata frame = frame_metadata("seed.toml", 0.25f, 1, "abc", 6);
  EXPECT_EQ(frame.at("ImageDescription"), "seed.toml t=0.250000 spp=1 frame=6 fingerprint=abc");
  EXPECT_EQ(fingerprint_from(frame.at(kFingerprintKey), frame.at("ImageDescription")), "abc");
}

}  // namespace
}  // namespace ms::test
