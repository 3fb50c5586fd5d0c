// Bounded work per draw: a frame is drawn as a grid of scissor rectangles,
// so no single draw covers more than kTileSize x kTileSize pixels (a long
// draw trips a GPU driver's watchdog; on llvmpipe it is the unit between
// --timeout checks). The viewport stays the whole frame, so gl_FragCoord,
// uResolution and uJitter mean exactly what they mean in one full draw and
// the image is bit-identical. And the memory a frame needs, checked against
// a budget before anything is allocated. No GL here.
#pragma once
#include <string>
#include <vector>

#include "core/memory_budget.h"

namespace ms {

inline constexpr int kTileSize = 512;

struct Tile {
  int x = 0, y = 0;  // lower-left corner, GL window coordinates
  int width = 0, height = 0;
};

// Near-equal tiles covering width x height, row by row from the bottom,
// each at most max_side pixels per side (max_side <= 0: one tile).
std::vector<Tile> split_tiles(int width, int height, int max_side = kTileSize);

// Bytes one frame holds at once: `gpu_targets` RGBA32F buffers on the GPU,
// plus the host copies read back and converted for writing (`aovs`: the
// AOV image beside the colour), times `host_frames` frames alive at once (a
// sequence queues finished frames for its writers). Samples accumulate in
// place, so spp adds time, not memory.
struct FrameMemory {
  double gpu_bytes = 0;
  double host_bytes = 0;
  bool aovs = false;
  double total() const { return gpu_bytes + host_bytes; }
};
FrameMemory frame_memory(int width, int height, int gpu_targets, bool aovs, int host_frames = 1);

// core/memory_budget.h's: 4 GiB, or half the machine's physical memory
// when that is less (a small CI box must refuse, not swap or get OOM-killed).
double frame_memory_budget();

// Throws bad_input (key "--size") with the figures when m is over budget:
// "image size WxH needs 6.9 GiB (2.3 GiB of GPU buffers, 4.6 GiB of host
// copies), over the 4.0 GiB memory budget", then ", and " + `also` (why
// it cannot be tiled) when given.
void check_frame_memory(const FrameMemory& m, int width, int height, const std::string& also = {});

// A still drawn piece by piece (render/tiled_still.h) when it is past the
// memory budget or the GL's size limit: bands of band_height rows, each
// drawn as tiles of at most tile_width columns into a tile-sized
// framebuffer. Both even, so each tile starts on an even pixel and the 2x2
// quads that derivatives (dFdx, fwidth) are taken over are those of one
// whole draw. tile_width 0: not tiled.
struct StillTiling {
  int tile_width = 0;
  int band_height = 0;
  bool tiled() const { return tile_width > 0; }
};

// The largest side of a tiled still: beyond it the float pixel coordinates
// stay exact (2^24), but files and times no longer make sense.
inline constexpr int kMaxTiledSide = 65536;

// How to draw a still of width x height: whole when it fits `max_w` x
// `max_h` (the GL's limit) and, with `gpu_targets` buffers and the AOVs,
// the memory budget; else in bands sized to a quarter of the budget (at
// most 512 rows) and tiles at most 4096 wide (within the GL's limit).
// `forced_side` > 0 tiles at any size, tiles at most that side (rounded
// down to even; tests). Throws bad_input (key "--size") past
// kMaxTiledSide, or when even a band of 2 rows is over the budget.
StillTiling plan_still_tiling(int width, int height, int max_w, int max_h, int gpu_targets, bool aovs,
                              int forced_side = 0);

// The memory a tiled still holds at once: one band (its tiles' GPU buffers
// counted as if one band-wide framebuffer, an upper bound) and its copies.
FrameMemory tiled_memory(int width, const StillTiling& t, int gpu_targets, bool aovs);


}  // namespace ms
