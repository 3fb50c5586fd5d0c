// live/: the pure pieces of the viewer: ranged scene uniforms parsed from
// GLSL and the frame-time medians.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

#include "live/frame_stats.h"
#include "live/overlay.h"
#include "render/aov.h"
#include "live/panel.h"
#include "live/param_reload.h"

namespace ms::live {
namespace {

TEST(LiveParams, RangedUniformsAreFound) {
  const auto params = parse_scene_params(
      "uniform float uTwist = 0.5;   // range(0, 2)\n"
      "uniform vec3 uTint = vec3(1.0, 0.8, 0.6); // color\n"
      "  uniform int uCount = 4; // how many: range(1, 16)\n"
      "uniform vec2 uOffset; // range(-1, 1)\n"
      "uniform float uPlain;  // set by the host\n"
      "uniform float uNoComment = 1.0;\n"
      "uniform vec3 uSplat = vec3(0.25); // range(0, 1)\n");
  ASSERT_EQ(params.size(), 5u);
  EXPECT_EQ(params[0].name, "uTwist");
  EXPECT_FLOAT_EQ(params[0].lo, 0.0f);
  EXPECT_FLOAT_EQ(params[0].hi, 2.0f);
  EXPECT_FLOAT_EQ(params[0].value[0], 0.5f);
  EXPECT_TRUE(params[1].color);
  EXPECT_EQ(params[1].components, 3);
  EXPECT_FLOAT_EQ(params[1].initial[1], 0.8f);
  EXPECT_TRUE(params[2].is_int);
  EXPECT_FLOAT_EQ(params[2].value[0], 4.0f);
  EXPECT_FLOAT_EQ(params[2].hi, 16.0f);
  EXPECT_EQ(params[3].components, 2);
  EXPECT_FLOAT_EQ(params[3].value[0], -1.0f);  // no initializer: the low end
  EXPECT_FLOAT_EQ(params[4].value[2], 0.25f);  // vec3(0.25) splats
}

TEST(LiveParams, BadRangesAndDuplicatesAreSkipped) {
  const auto params = parse_scene_params(
      "uniform float a = 1.0; // range(2, 1)\n"
      "uniform float b = 1.0; // range(0, x)\n"
      "uniform float c = 1.0; // range(0, 3)\n"
      "uniform float c = 1.0; // range(0, 3)\n");
  ASSERT_EQ(params.size(), 1u);
  EXPECT_EQ(params[0].name, "c");
}

TEST(LiveParams, ValuesSurviveAReloadUnlessTheFileChangedThem) {
  auto old = parse_scene_params("uniform float a = 1.0; // range(0, 2)\nuniform float b = 1.0; // range(0, 2)\n");
  old[0].value[0] = 1.5f;
  old[1].value[0] = 0.2f;
  auto fresh = parse_scene_params("uniform float a = 1.0; // range(0, 4)\nuniform float b = 0.7; // range(0, 2)\n");
  carry_over_values(fresh, old);
  EXPECT_FLOAT_EQ(fresh[0].value[0], 1.5f);  // same initializer: the user's value stays
  EXPECT_FLOAT_EQ(fresh[1].value[0], 0.7f);  // edited initializer: the file wins
}

TEST(LiveParams, CopiedDeclarationsReadBackTheSameValues) {
  auto params = parse_scene_params(
      "uniform float a = 0.5; // range(-1, 2)\n"
      "uniform vec3 c = vec3(1.0, 0.5, 0.25); // color\n"
      "uniform int n = 3; // range(1, 8)\n"
      "uniform vec2 o; // range(-2, 2)\n");
  params[0].value[0] = -0.75f;
  params[1].value = {0.1f, 0.2f, 0.3f, 0.0f};
  params[2].value[0] = 6.0f;
  params[3].value = {1.5f, -0.5f, 0.0f, 0.0f};
  const std::string text = param_declarations(params);
  EXPECT_NE(text.find("uniform float a = -0.75;  // range(-1.0, 2.0)"), std::string::npos) << text;
  const auto back = parse_scene_params(text);
  ASSERT_EQ(back.size(), params.size()) << text;
  for (size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].initial, params[i].value) << back[i].name;
    EXPECT_EQ(back[i].lo, params[i].lo);
    EXPECT_EQ(back[i].hi, params[i].hi);
    EXPECT_EQ(back[i].color, params[i].color);
  }
}

TEST(LiveFrameStats, MedianOverTheLastSecond) {
  EXPECT_DOUBLE_EQ(median_of({}), 0.0);
  EXPECT_DOUBLE_EQ(median_of({3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(median_of({4, 1, 3, 2}), 2.5);
  TimeSeries s(100);
  s.add(0.0, 100.0);  // older than a second at t = 1.5
  s.add(0.6, 100.0);
  s.add(1.0, 10.0);
  s.add(1.2, 12.0);
  s.add(1.5, 11.0);
  EXPECT_DOUBLE_EQ(s.median(1.5), 11.5);  // 100, 10, 12, 11 in (0.5, 1.5]
  EXPECT_DOUBLE_EQ(s.median(1.5, 0.6), 11.0);
}

TEST(LiveFrameStats, KeepsOnlyTheCapacity) {
  TimeSeries s(3);
  for (int i = 0; i < 10; ++i) s.add(i, i);
  EXPECT_EQ(s.values(), (std::vector<float>{7, 8, 9}));
}

// Debug views are shown as values, so the legend is the shader's ramp
// itself: its stops exactly, whatever the scene's exposure or tone map.
TEST(LiveLegend, IsTheShadersRampAsStored) {
  const glm::vec3 red = heat_legend_color(255.0f);
  EXPECT_NEAR(red.r, 1.0f, 1e-6f);
  EXPECT_NEAR(red.g, 0.0f, 1e-6f);
  const glm::vec3 green = heat_legend_color(15.0f);  // the middle stop (0, .85, .2)
  EXPECT_NEAR(green.g, 0.85f, 1e-6f);
  EXPECT_NEAR(green.b, 0.2f, 1e-6f);
  EXPECT_NEAR(heat_legend_color(3.0f).g, 0.35f, 1e-6f);  // the second stop
}

// The depth legend's ticks: ascending, 0 first and MAX_DIST last, where the
// shader's grey is 1 and 0.
TEST(LiveLegend, DepthTicksSpanTheShadersScale) {
  for (float far : {5.0f, 20.0f, 100.0f, 1000.0f}) {
    const std::vector<float> t = depth_legend_ticks(far);
    ASSERT_GE(t.size(), 2u);
    EXPECT_LE(t.size(), 6u);
    EXPECT_EQ(t.front(), 0.0f);
    EXPECT_EQ(t.back(), far);
    EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
    EXPECT_FLOAT_EQ(depth_shade(t.front(), far), 1.0f);
    EXPECT_FLOAT_EQ(depth_shade(t.back(), far), 0.0f);
  }
  EXPECT_EQ(depth_legend_ticks(100.0f), (std::vector<float>{0, 1, 3, 10, 30, 100}));
  EXPECT_NEAR(depth_shade(std::sqrt(101.0f) - 1.0f, 100.0f), 0.5f, 1e-5f);  // halfway on the log scale
}

}  // namespace
}  // namespace ms::live
