// write_level_set(): the grid is built and serialised by marchstudio-vdb.so
// (mesh/vdb_module.h), loaded here on the first .vdb; the bytes it hands
// back are written through io/atomic_file.h.
#include <dlfcn.h>

#include <cmath>
#include <mutex>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/module_file.h"
#include "mesh/mesh.h"
#include "mesh/vdb_module.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

static_assert(sizeof(glm::ivec3) == 3 * sizeof(std::int32_t), "LevelSetBand::ijk passes as int32 triples");

struct VdbModule {
  MarchVdbWrite write = nullptr;
  fs::path path;
  std::string error;  // why not, when write is null
};

const VdbModule& vdb_module() {
  static std::once_flag once;
  static VdbModule m;
  std::call_once(once, [] {
    m.path = module_path("MARCH_VDB_MODULE", kVdbModuleFile, MARCH_VDB_MODULE_DIR);
    void* lib = open_module(m.path, m.error);  // never dlclose'd: it lives as long as the process
    if (!lib) return;
    m.write = reinterpret_cast<MarchVdbWrite>(dlsym(lib, kVdbModuleSymbol));
    if (!m.write) m.error = std::string("no ") + kVdbModuleSymbol + " in it";
  });
  return m;
}

void check_band(const LevelSetBand& band, const fs::path& file) {
  if (!(band.voxel > 0.0) || !std::isfinite(band.voxel))
    fail_input("level set voxel size must be positive, not " + std::to_string(band.voxel), file.string());
  if (!(band.band > 0.0f) || !std::isfinite(band.band))
    fail_input("level set band must be positive, not " + std::to_string(band.band), file.string());
  if (band.ijk.size() != band.value.size())
    fail_input("level set has " + std::to_string(band.ijk.size()) + " voxels and " +
                   std::to_string(band.value.size()) + " values",
               file.string());
}

void append_bytes(void* user, const char* data, std::uint64_t n) {
  static_cast<std::string*>(user)->append(data, n);
}

}  // namespace

std::uint64_t write_level_set(const LevelSetBand& band, const fs::path& file) {
  check_band(band, file);
  const VdbModule& m = vdb_module();
  if (!m.write)
    throw Error({Exit::system, m.path.string(), 0, {}, "cannot load the OpenVDB module: " + m.error,
                 "keep it beside the marchstudio executable or in ../lib/marchstudio/ from it, or set "
                 "MARCH_VDB_MODULE to its path", {}});
  const MarchVdbBand b{band.name.c_str(),
                       band.voxel,
                       {band.origin.x, band.origin.y, band.origin.z},
                       band.band,
                       band.ijk.empty() ? nullptr : &band.ijk[0].x,
                       band.value.data(),
                       band.value.size()};
  std::string bytes;
  std::uint64_t active = 0;
  char err[512] = {};
  if (m.write(&b, append_bytes, &bytes, &active, err, sizeof err) != 0)
    fail_system(std::string("cannot make the OpenVDB grid: ") + err, file.string());
  write_file_atomic(file, bytes);
  return active;
}

}  // namespace ms
