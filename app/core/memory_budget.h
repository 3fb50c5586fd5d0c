// One memory budget for what a run may allocate at once: a frame and its
// copies (render/tiles.h), and every input whose size a file's header
// declares (an image, a texture, a cubemap's faces, an audio clip). A
// small file can declare gigabytes (a 69-byte PNG of 100000x100000), so
// inputs are checked from the header, before their pixels are allocated.
//
//   check_input_memory(4.0 * w * h * nc, "image of " + size, file.string());
#pragma once
#include <string>

namespace ms {

// 4 GiB, or half the machine's physical memory when that is less (a small
// CI box must refuse, not swap or get OOM-killed).
double memory_budget();

// "1.5 GiB" or "12 MiB".
std::string format_bytes(double bytes);

// Throws bad_input at `file`: "<what> needs 6.0 GiB, over the 4.0 GiB
// memory budget (hint)" when `bytes` is over memory_budget().
void check_input_memory(double bytes, const std::string& what, const std::string& file, const std::string& hint = {});

}  // namespace ms
