// How a huge still is split (render/tiles.h plan_still_tiling,
// render/tiled_still.h still_tiles): when it is tiled, that every pixel is
// drawn exactly once, that every tile starts on an even pixel (the 2x2
// quads derivatives use), bands from the top, and the memory a band takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "render/tiled_still.h"
#include "render/tiles.h"

namespace ms {
namespace {

constexpr int kGl = 16384;  // llvmpipe's GL_MAX_VIEWPORT_DIMS / GL_MAX_TEXTURE_SIZE

TEST(StillTiling, AFrameWithinTheLimitsIsNotTiled) {
  EXPECT_FALSE(plan_still_tiling(1920, 1080, kGl, kGl, 2, false).tiled());
  EXPECT_FALSE(plan_still_tiling(2048, 2048, kGl, kGl, 6, true).tiled());
}

TEST(StillTiling, PastTheBudgetOrTheGlLimitItIsTiledWithinBoth) {
  struct Case {
    int w, h, targets;
    bool aovs;
  };
  for (const Case& c : std::vector<Case>{{8200, 8200, 2, false}, {32768, 32768, 2, false}, {32768, 32768, 6, true},
                                         {20000, 100, 2, false}, {100, 20000, 2, false}, {65536, 65536, 6, true}}) {
    const StillTiling t = plan_still_tiling(c.w, c.h, kGl, kGl, c.targets, c.aovs);
    ASSERT_TRUE(t.tiled()) << c.w << "x" << c.h;
    EXPECT_LE(t.tile_width, kGl);
    EXPECT_LE(t.band_height, kGl);
    EXPECT_EQ(t.tile_width % 2, 0);
    EXPECT_EQ(t.band_height % 2, 0);
    EXPECT_LE(tiled_memory(c.w, t, c.targets, c.aovs).total(), 0.25 * frame_memory_budget() + 1.0)
        << "a band takes at most a quarter of the budget";
  }
  // The whole frame of the first case is over the budget: that is why it tiles.
  EXPECT_GT(frame_memory(8200, 8200, 2, false).total(), frame_memory_budget());
}

TEST(StillTiling, ForcedTilesAreAtMostTheSideRoundedDownToEven) {
  StillTiling t = plan_still_tiling(301, 203, kGl, kGl, 2, false, 64);
  EXPECT_EQ(t.tile_width, 62);  // 5 equal shares of 301: 61, rounded up to even
  EXPECT_EQ(t.band_height, 64);
  t = plan_still_tiling(301, 203, kGl, kGl, 2, false, 51);
  EXPECT_LE(t.tile_width, 50);
  EXPECT_EQ(t.band_height, 50);
}

TEST(StillTiling, PastTheLargestSideIsBadInput) {
  try {
    plan_still_tiling(kMaxTiledSide + 1, 10, kGl, kGl, 2, false);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().code, Exit::bad_input);
    EXPECT_EQ(e.info().key, "--size");
  }
}

TEST(StillTiles, CoverEveryPixelOnceFromTheTopOnEvenCorners) {
  for (const auto& [w, h, side] : std::vector<std::tuple<int, int, int>>{
           {301, 203, 64}, {301, 203, 50}, {64, 64, 64}, {7, 5, 2}, {32768, 1030, 4096}}) {
    const StillTiling t = plan_still_tiling(w, h, kGl, kGl, 2, false, side);
    const std::vector<Tile> tiles = still_tiles(w, h, t);
    std::vector<int> hits(static_cast<size_t>(w) * h, 0);
    int last_y = h;
    for (const Tile& tile : tiles) {
      EXPECT_EQ(tile.x % 2, 0);
      EXPECT_EQ(tile.y % 2, 0);
      EXPECT_LE(tile.width, t.tile_width);
      EXPECT_LE(tile.height, t.band_height);
      EXPECT_LE(tile.y, last_y) << "bands go from the top (GL's last rows) down";
      last_y = tile.y;
      for (int y = tile.y; y < tile.y + tile.height; ++y)
        for (int x = tile.x; x < tile.x + tile.width; ++x) ++hits[static_cast<size_t>(y) * w + x];
    }
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), static_cast<long>(hits.size())) << w << "x" << h;
  }
}

}  // namespace
}  // namespace ms
