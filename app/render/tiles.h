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

// The budget: 4 GiB, or half the machine's physical memory when that is
// less (a small CI box must refuse, not swap or get OOM-killed).
double frame_memory_budget();

// Throws bad_input (key "--size") with the figures when m is over budget:
// "image size WxH needs 6.9 GiB (2.3 GiB of GPU buffers, 4.6 GiB of host
// copies), over the 4.0 GiB memory budget".
void check_frame_memory(const FrameMemory& m, int width, int height);

// "1.5 GiB" / "320 MiB".
std::string format_bytes(double bytes);

}  // namespace ms
