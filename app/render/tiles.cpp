#include "render/tiles.h"

#include <algorithm>

#include "core/error.h"
#include "core/memory_budget.h"
#include "render/aov.h"

namespace ms {

std::vector<Tile> split_tiles(int width, int height, int max_side) {
  std::vector<Tile> tiles;
  if (width <= 0 || height <= 0) return tiles;
  if (max_side <= 0) max_side = std::max(width, height);
  // Equal shares rather than max_side and a sliver: 1100 -> 367+367+366.
  const int nx = (width + max_side - 1) / max_side, ny = (height + max_side - 1) / max_side;
  for (int j = 0; j < ny; ++j) {
    const int y0 = static_cast<int>(static_cast<long long>(height) * j / ny);
    const int y1 = static_cast<int>(static_cast<long long>(height) * (j + 1) / ny);
    for (int i = 0; i < nx; ++i) {
      const int x0 = static_cast<int>(static_cast<long long>(width) * i / nx);
      const int x1 = static_cast<int>(static_cast<long long>(width) * (i + 1) / nx);
      tiles.push_back({x0, y0, x1 - x0, y1 - y0});
    }
  }
  return tiles;
}

FrameMemory frame_memory(int width, int height, int gpu_targets, bool aovs, int host_frames) {
  const double px = static_cast<double>(width) * height;
  FrameMemory m;
  m.aovs = aovs;
  m.gpu_bytes = 16.0 * gpu_targets * px;  // RGBA32F
  // Read back: the colour as float RGBA, its 8-bit (or float) encoding for
  // the writer; with AOVs one attachment at a time, the AOV image and the
  // colour+AOV image that is written.
  const double nch = static_cast<double>(kAovChannels.size());
  m.host_bytes = 16.0 * px + 16.0 * px;
  if (aovs) m.host_bytes += 16.0 * px + 4.0 * nch * px + 4.0 * (4.0 + nch) * px;
  m.host_bytes *= std::max(host_frames, 1);
  return m;
}

double frame_memory_budget() { return memory_budget(); }

void check_frame_memory(const FrameMemory& m, int width, int height, const std::string& also) {
  const double budget = frame_memory_budget();
  if (m.total() <= budget) return;
  fail_input("image size " + std::to_string(width) + "x" + std::to_string(height) + " needs " + format_bytes(m.total()) +
                 " (" + format_bytes(m.gpu_bytes) + " of GPU buffers, " + format_bytes(m.host_bytes) +
                 " of host copies), over the " + format_bytes(budget) + " memory budget" +
                 (also.empty() ? "" : ", and " + also),
             {}, 0, "--size", m.aovs ? "render it smaller, or without --aov" : "render it smaller");
}

FrameMemory tiled_memory(int width, const StillTiling& t, int gpu_targets, bool aovs) {
  return frame_memory(width, t.band_height, gpu_targets, aovs);
}

namespace {

int even_at_most(int v) { return std::max(2, v - v % 2); }

}  // namespace

StillTiling plan_still_tiling(int width, int height, int max_w, int max_h, int gpu_targets, bool aovs,
                              int forced_side) {
  const bool fits = width <= max_w && height <= max_h &&
                    frame_memory(width, height, gpu_targets, aovs).total() <= frame_memory_budget();
  if (fits && forced_side <= 0) return {};
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width > kMaxTiledSide || height > kMaxTiledSide)
    fail_input("image size " + size + " is larger than " + std::to_string(kMaxTiledSide) + " pixels a side", {}, 0,
               "--size", "the largest tiled still is " + std::to_string(kMaxTiledSide) + "x" +
                             std::to_string(kMaxTiledSide));
  constexpr int kMaxBandRows = 512, kMaxTileWidth = 4096;
  StillTiling t;
  // Equal tiles across (an even width each, the last one the rest).
  const int cap = even_at_most(std::min({max_w, kMaxTileWidth, forced_side > 0 ? forced_side : kMaxTileWidth}));
  const int across = (width + cap - 1) / cap;
  t.tile_width = std::min(cap, even_at_most((width + across - 1) / across + 1));
  const double row_bytes = frame_memory(width, 1, gpu_targets, aovs).total();
  const int rows = static_cast<int>(std::min(1e9, 0.25 * frame_memory_budget() / row_bytes));
  t.band_height = even_at_most(std::min({rows, kMaxBandRows, max_h, forced_side > 0 ? forced_side : kMaxBandRows}));
  check_frame_memory(tiled_memory(width, t, gpu_targets, aovs), width, height);
  return t;
}

}  // namespace ms
