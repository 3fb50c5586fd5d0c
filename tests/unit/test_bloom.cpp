// [post.bloom] as the scene loader reads it (scene/load_post.h) and the
// bloom stage's sizes (render/bloom.h); the images are tests/cli/test_bloom.cpp's.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "render/bloom.h"
#include "scene/load.h"

namespace fs = std::filesystem;

namespace {

const fs::path kInline = fs::path(MARCH_TEST_DATA) / "scene" / "inline.toml";

// Lines 1-4; a case's body starts on line 5.
constexpr const char* kBase = "[scene]\nmap = \"seed.glsl\"\n[[materials]]\nname = \"floor\"\n";

ms::ErrorInfo error_of(const std::string& body) {
  try {
    ms::parse_scene(std::string(kBase) + body, kInline);
  } catch (const ms::Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error for:\n" << body;
  return {};
}

TEST(BloomScene, AbsentTableMeansNoBloom) {
  EXPECT_FALSE(ms::parse_scene(kBase, kInline).bloom.enabled);
  EXPECT_FALSE(ms::parse_scene(std::string(kBase) + "[post]\n", kInline).bloom.enabled);
}

TEST(BloomScene, DefaultsAndValues) {
  const ms::Bloom d = ms::parse_scene(std::string(kBase) + "[post.bloom]\n", kInline).bloom;
  EXPECT_TRUE(d.enabled);
  EXPECT_EQ(d.threshold, 1.0f);
  EXPECT_EQ(d.intensity, 0.5f);
  EXPECT_EQ(d.radius, 8.0f);
  EXPECT_EQ(d.scale, 0.3f);
  EXPECT_EQ(d.passes, 2);
  EXPECT_FALSE(d.exr);
  const ms::Bloom b = ms::parse_scene(std::string(kBase) +
                                          "[post.bloom]\nthreshold = 2.5\nintensity = 0\nradius = 16\n"
                                          "scale = 1\npasses = 8\nexr = true\n",
                                      kInline)
                          .bloom;
  EXPECT_EQ(b.threshold, 2.5f);
  EXPECT_EQ(b.intensity, 0.0f);
  EXPECT_EQ(b.radius, 16.0f);
  EXPECT_EQ(b.scale, 1.0f);
  EXPECT_EQ(b.passes, 8);
  EXPECT_TRUE(b.exr);
}

TEST(BloomScene, ErrorsNameLineAndKey) {
  ms::ErrorInfo e = error_of("[post.bloom]\nscale = 0.04\n");
  EXPECT_EQ(e.line, 6);
  EXPECT_EQ(e.key, "post.bloom.scale");
  e = error_of("[post.bloom]\npasses = 3\nradius = nan\n");
  EXPECT_EQ(e.line, 7);
  EXPECT_EQ(e.key, "post.bloom.radius");
  e = error_of("[post]\nbloom = 1\n");
  EXPECT_EQ(e.line, 6);
  EXPECT_EQ(e.key, "post.bloom");
  e = error_of("[post.bloom]\nthresold = 1\n");
  EXPECT_EQ(e.line, 6);
  EXPECT_NE(ms::format_error(e).find("did you mean 'threshold'"), std::string::npos) << ms::format_error(e);
}

TEST(BloomStage, Sizes) {
  EXPECT_EQ(ms::bloom_size(96, 0.25f), 24);
  EXPECT_EQ(ms::bloom_size(1280, 0.3f), 384);
  EXPECT_EQ(ms::bloom_size(720, 0.3f), 216);
  EXPECT_EQ(ms::bloom_size(1, 0.05f), 1);
  ms::Bloom b;
  b.radius = 8;
  b.scale = 0.5f;
  b.passes = 4;
  EXPECT_FLOAT_EQ(ms::bloom_pass_sigma(b), 2.0f);  // 4 passes of sigma 2 = one of sigma 4 = 8 x 0.5
  EXPECT_EQ(ms::bloom_half_taps(2.0f), 6);
  EXPECT_EQ(ms::bloom_half_taps(0.85f), 3);
  EXPECT_EQ(ms::bloom_half_taps(100.0f), ms::kBloomMaxHalf);
  EXPECT_EQ(ms::bloom_half_taps(0.0f), 0);
}

}  // namespace
