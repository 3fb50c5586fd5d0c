// A still too large for one framebuffer (past the memory budget or the
// GL's size limit; render/tiles.h plans it), drawn band by band from the
// top, each band as tiles into a tile-sized framebuffer. Every tile's draw
// sets uResolution / iResolution to the whole image and uPixelOffset to the
// tile's corner, so floor(gl_FragCoord.xy) + uPixelOffset + uJitter, the
// camera ray and the jitter are those of one whole draw: the image is
// bit-identical. Each finished band goes to `sink` (pipeline/ streams it to the
// file), so only a band is ever held. Stateless graphs only: a graph with
// buffers needs them whole-frame.
//
//   const StillTiling t = plan_still_tiling(w, h, max_w, max_h, targets, aovs);
//   render_still_tiled(renderer, graph, post, still, t, [&](StillBand& b) { out.write_rows(b.top, b.color); });
#pragma once
#include <functional>

#include "render/still.h"
#include "render/tiles.h"

namespace ms {

struct StillBand {
  int top = 0;     // its first row in the image, top row first
  Still pixels;    // width x rows: colour (flagged taken), AOVs when params.aovs
};

// Called after each tile: tiles done, tiles in all.
using TileDoneFn = std::function<void(int done, int total)>;

// The tiles of t, in drawing order: bands from the top, tiles left to right
// (GL coordinates, as split_tiles gives them).
std::vector<Tile> still_tiles(int width, int height, const StillTiling& t);

// Draws f (f.params: the whole image) tile by tile and hands each band to
// `sink`, top band first. Throws what FrameRenderer::draw throws (the
// deadline included); throws internal for a stateful graph.
void render_still_tiled(FrameRenderer& renderer, PassGraph& graph, const Program& post, const StillFrame& f,
                        const StillTiling& t, const std::function<void(StillBand&)>& sink,
                        const TileDoneFn& tile_done = {});
// The same with each tile drawn by `draw_tile` (a still of the tile's
// StillFrame): the compute dispatch's tiles (render/compute_frame.h).
using StillFn = std::function<Still(const StillFrame&)>;
void render_still_tiled(const StillFn& draw_tile, const PassGraph& graph, const StillFrame& f, const StillTiling& t,
                        const std::function<void(StillBand&)>& sink, const TileDoneFn& tile_done = {});

}  // namespace ms
