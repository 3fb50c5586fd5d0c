// A scene's surface as a mesh or a level set (docs/mesh.md): the scene's own
// map() sampled sparsely on the GPU (render/field_sampler.h), meshed by
// manifold dual contouring (mesh/dual_contour.h), checked, measured and
// written atomically. Any scene with a map() or a graph; a Shadertoy
// shader has no field and is refused.
//
//   MeshJob job;  job.frame.input = "part.toml";  job.output = "part.glb";
//   MeshReport r = mesh_scene(job, session, progress);   // throws ms::Error
//   std::puts(mesh_report_json(r).c_str());
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/field_source.h"
#include "mesh/mesh.h"
#include "mesh/mesh_check.h"
#include "pipeline/frame_job.h"
#include "pipeline/frame_session.h"

namespace ms {

// The most cells along the box's longest side: --resolution's limit, and
// so --voxel's floor (the box's longest side / 4096).
constexpr int kMaxMeshCells = 4096;

// The files a mesh at `file` is made of: the file, and an OBJ's .mtl
// beside it (mesh/mesh.h names it after the file).
std::vector<std::filesystem::path> mesh_files(const std::filesystem::path& file);

struct MeshBox {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

struct MeshJob {
  FrameJob frame;                  // input, backend, shader dir, preset, -D, --set, --uniform, graph, time, timeout, strict
  std::filesystem::path output;    // its extension picks the format (mesh/mesh.h)
  int resolution = 256;            // cells along the box's longest side
  double voxel = 0.0;              // > 0: the cell's size instead
  std::optional<MeshBox> bounds;   // none: the scene's [bounds]
  bool planes = false;             // the declared planes, cut by the box, are part of the solid
  int band = 3;                    // a level set's half-width in voxels
  // When given, the mesh is moved here once written; with `output` empty
  // too, nothing is written (the Python package's arrays). Not for .vdb.
  TriMesh* mesh_out = nullptr;
};

struct MeshReport {
  std::string output;
  std::vector<std::string> written;  // every file written (an OBJ's .mtl too), for stdout
  MeshFormat format = MeshFormat::obj;
  glm::ivec3 cells{0};
  double voxel = 0.0;
  std::size_t bricks = 0, samples = 0, readback_bytes = 0;
  std::size_t vertices = 0, triangles = 0, surface_cells = 0, split_cells = 0, untangled = 0;
  std::size_t band_voxels = 0;     // a level set's active voxels, as written
  std::size_t nonfinite = 0;       // values of map() read that were NaN or Inf
  MeshCheck check;
  MeshAccuracy accuracy;
  // setup: load, assemble, compile, a graph's pruning; sample_s includes it
  double setup_s = 0.0, sample_s = 0.0, mesh_s = 0.0, check_s = 0.0, write_s = 0.0, seconds = 0.0;
};

// Throws bad_input for a scene without a field, no box, an output of
// another extension, a --voxel under the floor; system for GL and write
// failures (no file left), a grid whose surface needs more than the memory
// budget (core/memory_budget.h; checked before the bricks are sampled),
// and past job.frame.timeout (a watchdog too, for a dispatch that never
// returns), naming the job by its frame.label or "the mesh export".
// Samples of map() that are NaN or Inf are a warning naming the count, or
// with job.frame.strict an error (exit 1) with nothing written. SIGINT or
// SIGTERM while writing leaves no temporary (io/temp_cleanup.h), nor the
// .mtl of an OBJ that did not land. `progress`, when given, hears each
// stage after the deadline is checked.
MeshReport mesh_scene(const MeshJob& job, FrameSession& session, const MeshProgress& progress = {});

std::string mesh_report_json(const MeshReport& r);   // one object, schema marchstudio.mesh/1
std::vector<std::string> mesh_report_lines(const MeshReport& r);  // -v
std::string mesh_summary(const MeshReport& r);       // one line: what was written

}  // namespace ms
