// The one function marchstudio-vdb.so exports, in plain C types: the module
// holds every OpenVDB call (OpenVDB brings TBB, Blosc, Imath and Boost,
// ~20 libraries), dlopen'd by write_level_set() (level_set.cpp) when a .vdb
// is written, so that no other run loads them.
//
//   MarchVdbBand b{name, voxel, {ox, oy, oz}, band, ijk, value, count};
//   std::string bytes, err(256, '\0');
//   std::uint64_t active = 0;
//   if (write(&b, append_to_string, &bytes, &active, err.data(), err.size()) != 0) ...
//
// The module serialises the grid to memory and hands the bytes back through
// `sink`; the caller writes them through io/atomic_file.h, so the atomic
// write stays in one place and no library opens the target.
#pragma once
#include <cstdint>

extern "C" {

struct MarchVdbBand {
  const char* name;         // the grid's name, NUL-terminated
  double voxel;             // world units per voxel
  double origin[3];         // world position of voxel (0, 0, 0)
  float band;               // the background: half-width of the band, world units
  const std::int32_t* ijk;  // 3 per voxel
  const float* value;       // 1 per voxel: signed distance, negative inside
  std::uint64_t count;
};

// Receives the file's bytes, in one or more pieces, in order.
typedef void (*MarchVdbSink)(void* user, const char* data, std::uint64_t n);

// 0 when written, with the grid's active voxel count in *active (what a
// reader of the file counts); else not, with a NUL-terminated message in
// err[0, err_size). Never throws.
typedef int (*MarchVdbWrite)(const MarchVdbBand* band, MarchVdbSink sink, void* user, std::uint64_t* active,
                             char* err, std::uint64_t err_size);
}

namespace ms {
inline constexpr const char* kVdbModuleSymbol = "marchstudio_vdb_write";
inline constexpr const char* kVdbModuleFile = "marchstudio-vdb.so";
}  // namespace ms
