// Facts about Shadertoy's own media library that decide pixels: which of
// its textures it uploads as one channel (they sample as (v, 0, 0, 1)), and
// the size and kind of the noise textures marchstudio stands in for when
// the file is not at hand. Media are named /media/a/<sha256>.<ext>; the
// table is keyed by that hash. No pixels of Shadertoy's are here.
#pragma once
#include <string>
#include <string_view>

namespace ms {

struct ShadertoyMedia {
  std::string_view hash;
  std::string_view name;   // as the site names it ("Gray Noise Medium")
  bool single_channel;     // uploaded as R8
  int noise_size;          // > 0: a noise texture of this size, which marchstudio can stand in for
  bool volume;             // a 3D texture (noise_size^3), read through a volume input
};

// The entry for a src ("/media/a/<hash>.png") or a bare file name, or null.
const ShadertoyMedia* find_shadertoy_media(std::string_view src);

}  // namespace ms
