#include "render/tiled_still.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"

namespace ms {
namespace {

Image blank(int width, int height, const std::vector<std::string>& channels) {
  Image img;
  img.width = width;
  img.height = height;
  img.channels = channels;
  img.pixels.assign(static_cast<size_t>(width) * height * channels.size(), 0.0f);
  return img;
}

// A tile's rows into its band's at column x0 (both top row first, equally tall).
void put_columns(Image& band, const Image& tile, int x0) {
  const size_t nch = tile.channels.size();
  for (int y = 0; y < tile.height; ++y)
    std::memcpy(band.pixels.data() + (static_cast<size_t>(y) * band.width + x0) * nch,
                tile.pixels.data() + static_cast<size_t>(y) * tile.width * nch, tile.width * nch * sizeof(float));
}

}  // namespace

std::vector<Tile> still_tiles(int width, int height, const StillTiling& t) {
  std::vector<Tile> out;
  if (!t.tiled() || width <= 0 || height <= 0) return out;
  // Bands start on multiples of band_height from GL's bottom row (even), so
  // the short band, if any, is the top one, drawn first.
  const int bands = (height + t.band_height - 1) / t.band_height;
  for (int j = bands - 1; j >= 0; --j) {
    const int y0 = j * t.band_height, rows = std::min(height, y0 + t.band_height) - y0;
    for (int x0 = 0; x0 < width; x0 += t.tile_width) out.push_back({x0, y0, std::min(t.tile_width, width - x0), rows});
  }
  return out;
}

void render_still_tiled(FrameRenderer& renderer, PassGraph& graph, const Program& post, const StillFrame& f,
                        const StillTiling& t, const std::function<void(StillBand&)>& sink,
                        const TileDoneFn& tile_done) {
  render_still_tiled([&](const StillFrame& piece) { return render_still(renderer, graph, post, piece); }, graph, f, t,
                     sink, tile_done);
}

void render_still_tiled(const StillFn& draw_tile, const PassGraph& graph, const StillFrame& f, const StillTiling& t,
                        const std::function<void(StillBand&)>& sink, const TileDoneFn& tile_done) {
  if (graph.stateful()) fail_system("internal: a graph with buffers cannot be drawn in tiles");
  const int width = f.params.width, height = f.params.height;
  const std::vector<Tile> tiles = still_tiles(width, height, t);
  StillBand band;
  for (size_t i = 0; i < tiles.size(); ++i) {
    const Tile& tile = tiles[i];
    StillFrame piece = f;
    FrameParams& p = piece.params;
    p.width = tile.width;
    p.height = tile.height;
    p.image_width = width;
    p.image_height = height;
    p.offset_x = tile.x;
    p.offset_y = tile.y;
    const Still s = draw_tile(piece);
    if (tile.x == 0) {
      band = StillBand{};
      band.top = height - (tile.y + tile.height);
      band.pixels.color = blank(width, tile.height, s.color.channels);
      if (f.params.aovs) band.pixels.aovs = blank(width, tile.height, s.aovs.channels);
    }
    put_columns(band.pixels.color, s.color, tile.x);
    if (f.params.aovs) put_columns(band.pixels.aovs, s.aovs, tile.x);
    band.pixels.flagged += s.flagged;
    if (tile_done) tile_done(static_cast<int>(i) + 1, static_cast<int>(tiles.size()));
    if (tile.x + tile.width == width) sink(band);
  }
}

}  // namespace ms
