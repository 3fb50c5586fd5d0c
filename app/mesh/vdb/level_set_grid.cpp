// marchstudio-vdb.so's one export (mesh/vdb_module.h): a narrow band of
// signed distances to an OpenVDB level-set FloatGrid, serialised in memory.
// exports.map hides every other symbol: OpenVDB's headers instantiate
// classes with default visibility, and a copy exported from a module that
// was dlopen'd RTLD_LOCAL would interpose libopenvdb's own (a crash inside
// openvdb::initialize()).
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>
#include <type_traits>

#include "mesh/vdb_module.h"

namespace {

openvdb::FloatGrid::Ptr band_grid(const MarchVdbBand& b) {
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(b.band);
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  grid->setName(b.name ? b.name : "");
  openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(b.voxel);
  xform->postTranslate(openvdb::Vec3d(b.origin[0], b.origin[1], b.origin[2]));
  grid->setTransform(xform);
  openvdb::FloatGrid::Accessor acc = grid->getAccessor();
  for (std::uint64_t i = 0; i < b.count; ++i)
    acc.setValue(openvdb::Coord(b.ijk[3 * i], b.ijk[3 * i + 1], b.ijk[3 * i + 2]), b.value[i]);
  // The band's signs fill the rest: inactive voxels and tiles become
  // -band inside and +band outside, as a level set's readers expect.
  openvdb::tools::signedFloodFill(grid->tree());
  openvdb::tools::pruneLevelSet(grid->tree());
  return grid;
}

void set_error(char* err, std::uint64_t err_size, const char* what) {
  if (!err || err_size == 0) return;
  const std::size_t n = std::min<std::size_t>(std::strlen(what), err_size - 1);
  std::memcpy(err, what, n);
  err[n] = '\0';
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int marchstudio_vdb_write(const MarchVdbBand* band,
                                                                           MarchVdbSink sink, void* user,
                                                                           std::uint64_t* active, char* err,
                                                                           std::uint64_t err_size) {
  try {
    openvdb::initialize();
    const openvdb::FloatGrid::Ptr grid = band_grid(*band);
    *active = grid->activeVoxelCount();
    openvdb::GridPtrVec grids{grid};
    std::ostringstream os(std::ios::binary);
    openvdb::io::Stream(os).write(grids);
    const std::string bytes = os.str();
    sink(user, bytes.data(), bytes.size());
    return 0;
  } catch (const std::exception& e) {
    set_error(err, err_size, e.what());
  } catch (...) {
    set_error(err, err_size, "unknown error");
  }
  return 1;
}

static_assert(std::is_same_v<decltype(&marchstudio_vdb_write), MarchVdbWrite>, "mesh/vdb_module.h's signature");
